"""A construction told step by step, as a lecture: slides (PDF), numbered SVG frames, an animated
SVG, and one self-contained HTML page.

All four are drawn from the same :class:`~graphmethods.scene.steps.BuildUp`: step k shows the
earlier steps in grey and step k's own elements in colour, with its caption under the figure.

- :func:`pdf_bytes`: one page per step (the step figure's page: a 16:9 slide or a sheet).
- :func:`svg_frames`: one SVG document per step.
- :func:`animated_svg`: one SVG that plays the steps by itself (SMIL ``<animate>`` of each
  layer's visibility, no script), ``seconds`` per step, looping; a viewer without SMIL shows the
  last step.
- :func:`html_page`: one HTML file with the figure inline, buttons and the arrow keys to step
  forward and back, the caption of each step, ``#step=k`` in the address to open at step k; no
  external file and no network (its Content-Security-Policy forbids any request).

Output is deterministic: the same construction gives the same bytes.

>>> from graphmethods.scene import Page, Scene, Text, Line
>>> from graphmethods.scene.steps import partition
>>> fig = Scene(Page("A4"), (Line((20, 40), (80, 40), name="axis"), Line((20, 40), (50, 10), name="ray")))
>>> bu = partition(fig, [("Axis", "axis"), ("Ray", "ray")], caption_box=(10, 180, 287, 200))
>>> doc = animated_svg(bu, seconds=2.0)
>>> doc.count("<animate "), 'dur="4s"' in doc
(3, True)
>>> "<script>" in html_page(bu) and "http://" not in html_page(bu).replace("http://www.w3.org", "")
True
"""

from __future__ import annotations

import html as _html
import json
import os
import pathlib
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterable

from graphmethods.errors import InputError
from graphmethods.render import svg as _svg
from graphmethods.render.files import check_target, write_set
from graphmethods.scene import markup
from graphmethods.scene.notation import get as get_notation
from graphmethods.scene.numbers import format_mm as fmt
from graphmethods.scene.scene import Scene, make_id
from graphmethods.scene.steps import NEW_COLOUR, OLD_COLOUR, BuildUp

SVG_NS = "http://www.w3.org/2000/svg"
FORMATS = ("pdf", "svg", "html", "animated-svg")

def _check(bu: object) -> BuildUp:
    if not isinstance(bu, BuildUp):
        raise InputError(f"expected the steps of a construction (graphmethods.sheets.steps), got {type(bu).__name__}")
    return bu


# ----------------------------------------------------------------------------- slides and frames

def slides(bu: BuildUp) -> list[Scene]:
    """One scene per step: earlier steps grey, this step in colour, its caption under the figure."""
    bu = _check(bu)
    return [bu.slide(k) for k in range(1, len(bu) + 1)]


def pdf_bytes(bu: BuildUp) -> bytes:
    """A PDF with one page per step."""
    from graphmethods.render import pdf

    return pdf.to_bytes(slides(bu))


def svg_frames(bu: BuildUp) -> list[str]:
    """One SVG document per step (str), step 1 first."""
    return [_svg.to_string(s) for s in slides(bu)]


# ----------------------------------------------------------------------------- layers

def _fragment(scene: Scene, prefix: str) -> list[ET.Element]:
    """The drawn children of ``scene``'s SVG root group, their ids prefixed (unique in one document)."""
    root = ET.fromstring(_svg.to_string(scene).split("?>", 1)[1])
    body = [c for c in root if c.tag == f"{{{SVG_NS}}}g"]
    out = list(body[0]) if body else []
    for el in out:
        for sub in el.iter():
            if "id" in sub.attrib:
                sub.set("id", prefix + (sub.get("id") or ""))
    return out


def _layers(bu: BuildUp, *, captions: bool) -> list[tuple[str, str, int, list[ET.Element]]]:
    """The base (page frame and title block) and, per step, the grey and the coloured layer:
    a list of (id, kind, step, children)."""
    fig = bu.figure
    bare = fig.page.with_(frame=False, title_block=None)
    base = Scene(fig.page, (), name=fig.name)
    out = [("base", "base", 0, _fragment(base, "base-"))]
    for k in range(1, len(bu) + 1):
        if k < len(bu):
            old = Scene(bare, bu.layer(k, OLD_COLOUR), name=fig.name)
            out.append((f"old-{k}", "old", k, _fragment(old, f"old-{k}-")))
        new_els = bu.layer(k, NEW_COLOUR) + ((bu.caption_element(k),) if captions else ())
        out.append((f"new-{k}", "new", k, _fragment(Scene(bare, new_els, name=fig.name), f"new-{k}-")))
    return out


def _root(bu: BuildUp, *, height_mm: float | None = None) -> ET.Element:
    fig = bu.figure
    W, H = fmt(fig.page.width_mm), fmt(fig.page.height_mm if height_mm is None else height_mm)
    root = ET.Element(f"{{{SVG_NS}}}svg", {"width": f"{W}mm", "height": f"{H}mm", "viewBox": f"0 0 {W} {H}",
                                           "version": "1.1"})
    title = ET.SubElement(root, f"{{{SVG_NS}}}title")
    title.text = _svg.clean_text(markup.plain(fig.title))
    return root


def _group(parent: ET.Element, lid: str, kind: str, step: int, children: Iterable[ET.Element],
           visible: bool) -> ET.Element:
    g = ET.SubElement(parent, f"{{{SVG_NS}}}g", {"id": lid})
    if kind != "base":
        g.set("class", kind)
        g.set("data-step", str(step))
        if not visible:
            g.set("visibility", "hidden")
    g.extend(children)
    return g


def _serialise(root: ET.Element) -> str:
    ET.register_namespace("", SVG_NS)
    _svg.indent(root)
    return ET.tostring(root, encoding="unicode")


def _frac(i: int, n: int) -> str:
    return f"{i / n:.6f}".rstrip("0").rstrip(".") or "0"


def visible_window(kind: str, step: int, n: int) -> tuple[int, int]:
    """The steps (first, last), 1-based, during which a layer is shown: a step's coloured layer at that
    step only, its grey layer from the next step to the last.

    >>> visible_window("new", 2, 5), visible_window("old", 2, 5)
    ((2, 2), (3, 5))
    """
    return (step, step) if kind == "new" else (step + 1, n)


def animated_svg(bu: BuildUp, *, seconds: float = 3.0) -> str:
    """One SVG document that plays the steps by itself, ``seconds`` per step, looping (SMIL, no script).

    Each layer's ``visibility`` is animated (discrete) over one cycle of ``n × seconds``; without
    SMIL a viewer shows the last step.
    """
    bu = _check(bu)
    if not (isinstance(seconds, (int, float)) and 0.1 <= float(seconds) <= 600):
        raise InputError(f"seconds per step must be a number from 0.1 to 600, got {seconds!r}")
    n = len(bu)
    fig = bu.figure
    root = _root(bu)
    body = ET.SubElement(root, f"{{{SVG_NS}}}g", {"id": make_id(fig.name), "font-family": _svg.FONT_FAMILY,
                                                    "stroke-linejoin": "round"})
    dur = f"{fmt(float(seconds) * n)}s"
    for lid, kind, step, children in _layers(bu, captions=True):
        if kind == "base":
            _group(body, lid, kind, step, children, True)
            continue
        first, last = visible_window(kind, step, n)
        g = _group(body, lid, kind, step, children, first <= n <= last)
        if first == 1 and last == n:
            continue
        values, times = [], []
        if first > 1:
            values.append("hidden")
            times.append("0")
        values.append("visible")
        times.append(_frac(first - 1, n))
        if last < n:
            values.append("hidden")
            times.append(_frac(last, n))
        anim = ET.Element(f"{{{SVG_NS}}}animate", {"attributeName": "visibility", "calcMode": "discrete",
                                                   "values": ";".join(values), "keyTimes": ";".join(times),
                                                   "dur": dur, "begin": "0s", "repeatCount": "indefinite"})
        g.insert(0, anim)
    return '<?xml version="1.0" encoding="utf-8"?>\n' + _serialise(root) + "\n"


# ----------------------------------------------------------------------------- HTML

def caption_html(text: str) -> str:
    """A caption's markup as HTML: sub- and superscripts as ``<sub>``/``<sup>``, the rest escaped.

    >>> caption_html("v_{BA} ⊥ AB & <x>")
    'v<sub>BA</sub> ⊥ AB &amp; &lt;x&gt;'
    """
    out = []
    for chunk, shift in markup.parse(text):
        t = _html.escape(chunk, quote=False)
        out.append(f"<sub>{t}</sub>" if shift < 0 else f"<sup>{t}</sup>" if shift > 0 else t)
    return "".join(out)


_CSS = """
html,body{margin:0;background:#f4f4f2;color:#111;font-family:'DejaVu Sans','Liberation Sans',Arial,
'Noto Sans CJK SC','Microsoft YaHei','PingFang SC',sans-serif}
main{max-width:1400px;margin:0 auto;padding:12px 16px}
figure{margin:0;background:#fff;box-shadow:0 1px 4px rgba(0,0,0,.25)}
figure svg{display:block;width:100%;height:auto}
#caption{font-size:1.6rem;line-height:1.35;padding:10px 16px 14px;min-height:2.8em;border-top:1px solid #ddd}
#caption .n{color:#c62828;font-weight:bold;margin-right:.4em}
nav{display:flex;align-items:center;gap:14px;margin-top:12px;font-size:1.2rem}
button{font:inherit;padding:6px 18px;border:1px solid #888;border-radius:4px;background:#fff;cursor:pointer}
button:disabled{opacity:.4;cursor:default}
#keys{margin-left:auto;color:#666;font-size:.95rem}
""".strip()

_JS = """
(function () {
  var svg = document.getElementById('figure');
  var layers = svg.querySelectorAll('g[data-step]');
  var texts = document.querySelectorAll('#captions > p');
  var n = texts.length, k = 1;
  var caption = document.getElementById('caption');
  var counter = document.getElementById('counter');
  var prev = document.getElementById('prev'), next = document.getElementById('next');
  var template = counter.getAttribute('data-template');
  function show(j) {
    k = Math.max(1, Math.min(n, j));
    for (var i = 0; i < layers.length; i++) {
      var s = +layers[i].getAttribute('data-step');
      var old = layers[i].getAttribute('class') === 'old';
      layers[i].style.display = (old ? s < k : s === k) ? '' : 'none';
    }
    caption.innerHTML = '<span class="n">' + k + '.</span>' + texts[k - 1].innerHTML;
    counter.textContent = template.replace('{k}', k).replace('{n}', n);
    prev.disabled = k === 1;
    next.disabled = k === n;
    document.body.setAttribute('data-step', String(k));
    try { history.replaceState(null, '', '#step=' + k); } catch (e) { }
  }
  prev.addEventListener('click', function () { show(k - 1); });
  next.addEventListener('click', function () { show(k + 1); });
  document.addEventListener('keydown', function (ev) {
    if (ev.altKey || ev.ctrlKey || ev.metaKey) { return; }
    var key = ev.key;
    if (key === 'ArrowRight' || key === 'PageDown') { show(k + 1); }
    else if (key === 'ArrowLeft' || key === 'PageUp') { show(k - 1); }
    else if (key === 'Home') { show(1); }
    else if (key === 'End') { show(n); }
    else { return; }
    ev.preventDefault();
  });
  var m = /step=(\\d+)/.exec(location.hash);
  show(m ? parseInt(m[1], 10) : 1);
})();
""".strip()


def html_page(bu: BuildUp) -> str:
    """One self-contained HTML page that steps through the construction (see the module docstring).

    The figure is inline SVG (its caption band left out: the caption is HTML text under it); every
    step's caption is in the page; a small script shows step k on the buttons, the arrow keys
    (← →, PageUp/PageDown, Home/End) and ``#step=k``. Without script the page shows step 1 and
    the list of every step's caption.
    """
    bu = _check(bu)
    fig = bu.figure
    nt = get_notation(fig.notation)
    n = len(bu)
    root = _root(bu, height_mm=bu.caption_box[1])
    root.set("id", "figure")
    root.set("role", "img")
    body = ET.SubElement(root, f"{{{SVG_NS}}}g", {"id": make_id(fig.name), "font-family": _svg.FONT_FAMILY,
                                                    "stroke-linejoin": "round"})
    for lid, kind, step, children in _layers(bu, captions=False):
        g = _group(body, lid, kind, step, children, True)
        if kind != "base":
            g.attrib.pop("visibility", None)
            if not (kind == "new" and step == 1):
                g.set("style", "display:none")
    svg_text = _serialise(root)
    title = _html.escape(markup.plain(fig.title), quote=False)
    caps = "\n".join(f'<p data-step="{k}">{caption_html(c)}</p>' for k, c in enumerate(bu.captions(), start=1))
    counter = nt.word("steps.counter")
    csp = "default-src 'none'; style-src 'unsafe-inline'; script-src 'unsafe-inline'; img-src data:"
    first = f'<span class="n">1.</span>{caption_html(bu.captions()[0])}'
    return f"""<!DOCTYPE html>
<html lang="{nt.code}">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta http-equiv="Content-Security-Policy" content="{csp}">
<title>{title}</title>
<style>
{_CSS}
</style>
<noscript><style>#captions[hidden]{{display:block}} nav{{display:none}}</style></noscript>
</head>
<body data-step="1">
<main>
<figure>
{svg_text}
<figcaption id="caption" aria-live="polite">{first}</figcaption>
</figure>
<nav>
<button id="prev" type="button" disabled>{_html.escape(nt.word("steps.back"))}</button>
<span id="counter" data-template="{_html.escape(counter)}">{_html.escape(counter.format(k=1, n=n))}</span>
<button id="next" type="button">{_html.escape(nt.word("steps.next"))}</button>
<span id="keys">{_html.escape(nt.word("steps.keys"))}</span>
</nav>
<div id="captions" hidden>
{caps}
</div>
</main>
<script>
{_JS}
</script>
</body>
</html>
"""


# ----------------------------------------------------------------------------- files

def outputs(bu: BuildUp, fmt_: str, path: str | os.PathLike[str], *,
            seconds: float = 3.0) -> list[tuple[pathlib.Path, bytes]]:
    """The files a format writes, with their bytes: one file, or for ``svg`` one frame per step named
    ``STEM-01.svg``, ``STEM-02.svg``, … beside ``path``; ``seconds`` per step of an animated SVG."""
    bu = _check(bu)
    path = pathlib.Path(path)
    if fmt_ == "pdf":
        return [(path, pdf_bytes(bu))]
    if fmt_ == "html":
        return [(path, html_page(bu).encode("utf-8"))]
    if fmt_ == "animated-svg":
        return [(path, animated_svg(bu, seconds=seconds).encode("utf-8"))]
    if fmt_ == "svg":
        stem = path.name[: -len(path.suffix)] if path.suffix.lower() == ".svg" else path.name
        width = max(2, len(str(len(bu))))
        return [(path.parent / f"{stem}-{k:0{width}d}.svg", doc.encode("utf-8"))
                for k, doc in enumerate(svg_frames(bu), start=1)]
    raise InputError(f"format {fmt_!r}: use one of {', '.join(FORMATS)}")


def save(bu: BuildUp, path: str | os.PathLike[str], fmt_: str, *, overwrite: bool = False,
         seconds: float = 3.0) -> list[pathlib.Path]:
    """Write the construction as ``fmt_`` (pdf, svg frames, html, animated-svg) to ``path``.

    Everything is built before the first file is written, an existing file is kept unless
    ``overwrite``, each file is written atomically, and an error leaves none of the files behind.

    Returns
    -------
    list of pathlib.Path
        The files written.
    """
    files = outputs(bu, fmt_, path, seconds=seconds)
    for target, _ in files:                     # a missing folder or an existing file: refused, nothing written
        check_target(target, overwrite=overwrite)
    folder = pathlib.Path(path).parent          # every file of a construction goes beside ``path``
    stale: list[str] = []
    if fmt_ == "svg" and overwrite and folder.is_dir():     # frames of an earlier, longer build go too
        stem = files[0][0].name.rsplit("-", 1)[0]
        frame = re.compile(re.escape(stem) + r"-\d+\.svg")
        stale = sorted(p.name for p in folder.iterdir() if frame.fullmatch(p.name) and p.is_file())
    return write_set(folder, {p.name: data for p, data in files}, overwrite=overwrite, stale=stale,
                     what="steps folder")


def manifest(bu: BuildUp) -> str:
    """The steps as JSON: number, caption (plain text) and element names, for scripts and tests."""
    return json.dumps([{"step": k, "caption": markup.plain(s.caption),
                        "elements": [bu.figure.elements[i].name for i in s.elements]}
                       for k, s in enumerate(bu.steps, start=1)], ensure_ascii=False, indent=1)
