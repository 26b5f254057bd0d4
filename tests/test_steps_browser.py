"""The lecture page in a real browser: headless Chromium, network blocked, driven by the arrow keys.

Skipped, with the reason, where no Chromium is installed (Debian's ``chromium``; ``.ci/run``
installs it where apt-get can). Screenshots go to ``GRAPHMETHODS_SCREENSHOTS`` when that names a
folder (to look at them), else to the test's temporary folder.
"""

import io
import os
import pathlib

import numpy as np
import pytest
from browser import Browser, find_chromium

from graphmethods.render import steps as R
from graphmethods.scene import markup
from graphmethods.sheets import steps as S

pytestmark = pytest.mark.skipif(find_chromium() is None,
                                reason="no Chromium on PATH (Debian package chromium; .ci/run installs it where "
                                       "apt-get is available): the browser test of the lecture page cannot run")

STATE = """(() => {
  const layers = Array.from(document.querySelectorAll('#figure g[data-step]'));
  return {
    step: document.body.getAttribute('data-step'),
    caption: document.getElementById('caption').textContent,
    counter: document.getElementById('counter').textContent,
    shown: layers.filter(g => getComputedStyle(g).display !== 'none').map(g => g.id),
    prev: document.getElementById('prev').disabled,
    next: document.getElementById('next').disabled,
    hash: location.hash,
  };
})()"""


def _pixels(png: bytes) -> np.ndarray:
    import matplotlib.image as mpimg

    return mpimg.imread(io.BytesIO(png), format="png")[:, :, :3]


def _red(img: np.ndarray) -> int:
    """Pixels of the new step's colour (#c62828, antialiased)."""
    r, g, b = img[:, :, 0], img[:, :, 1], img[:, :, 2]
    return int(np.sum((r > 0.6) & (g < 0.45) & (b < 0.45) & (r - g > 0.35)))


def _figure(browser, img: np.ndarray) -> np.ndarray:
    """The part of a screenshot showing the figure and its caption (the buttons' focus rings left out)."""
    r = browser.evaluate("(() => { const b = document.querySelector('figure').getBoundingClientRect(); "
                         "return [b.left, b.top, b.right, b.bottom].map(Math.round); })()")
    return img[r[1]:r[3], r[0]:r[2]]


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    """The same picture: no more than 20 pixels differ by more than 10 % (Chromium's software raster
    antialiases a repainted line a shade differently now and then; a step shown differs by thousands)."""
    return a.shape == b.shape and int(np.count_nonzero(np.abs(a - b).max(axis=2) > 0.1)) <= 20


def _shots_dir(tmp_path) -> pathlib.Path:
    d = os.environ.get("GRAPHMETHODS_SCREENSHOTS")
    if d and pathlib.Path(d).is_dir():
        return pathlib.Path(d)
    return tmp_path


def _expected(bu, k):
    return [f"old-{j}" for j in range(1, k)] + [f"new-{k}"]


@pytest.fixture(scope="module")
def browser():
    try:
        b = Browser(width=1400, height=900)
    except (OSError, RuntimeError, TimeoutError, ConnectionError) as exc:
        pytest.skip(f"Chromium ({find_chromium()}) is installed but did not start headless here: {exc}")
    with b:
        yield b


@pytest.mark.parametrize("case,figure,lang,k", [("press", "velocity-plan", "en", 4),
                                                ("press", "wittenbauer", "ru", 5),
                                                ("W1", "energy-indicator", "zh", 3),
                                                ("press", "force-plans", "ru", 4)])
def test_the_arrow_keys_step_through_the_construction_offline(browser, tmp_path, case, figure, lang, k):
    bu = S.build(case, figure, position=3 if figure == "force-plans" else None, notation=lang)
    n = len(bu)
    page = tmp_path / f"{case}_{figure}_{lang}.html"
    page.write_text(R.html_page(bu), encoding="utf-8")
    url = page.as_uri()
    browser.events.clear()
    browser.open(url)
    state = browser.evaluate(STATE)
    assert state["step"] == "1" and state["shown"] == ["new-1"] and state["prev"] and not state["next"]
    first = _pixels(browser.screenshot())
    # press → k − 1 times: the page's own keydown handler moves to step k
    for _ in range(k - 1):
        browser.press("ArrowRight")
    state = browser.evaluate(STATE)
    caption = markup.plain(bu.captions()[k - 1])
    assert state["step"] == str(k) and state["shown"] == _expected(bu, k)
    assert state["caption"] == f"{k}.{caption}"
    assert str(k) in state["counter"] and str(n) in state["counter"] and state["hash"] == f"#step={k}"
    shot = browser.screenshot()
    (_shots_dir(tmp_path) / f"{case}_{figure}_{lang}_step{k}.png").write_bytes(shot)
    at_k = _pixels(shot)
    assert _red(at_k) > 50, "the new step is drawn in colour"
    assert not _same(at_k, first)
    # ← goes back one step, and → again forward: the same picture as before
    browser.press("ArrowLeft")
    assert browser.evaluate(STATE)["shown"] == _expected(bu, k - 1)
    browser.press("ArrowRight")
    assert _same(_figure(browser, _pixels(browser.screenshot())), _figure(browser, at_k))
    # End and Home, and the buttons
    browser.press("End")
    state = browser.evaluate(STATE)
    assert state["step"] == str(n) and state["next"] and state["shown"] == _expected(bu, n)
    browser.press("ArrowRight")                       # no step past the last
    assert browser.evaluate(STATE)["step"] == str(n)
    browser.evaluate("document.getElementById('prev').click()")
    assert browser.evaluate(STATE)["step"] == str(n - 1)
    browser.press("Home")
    assert browser.evaluate(STATE)["shown"] == ["new-1"]
    # opening the page at #step=k shows the same picture as the keys did (a new load, not a jump in the page)
    browser.open("about:blank")
    browser.open(url + f"#step={k}")
    assert browser.evaluate(STATE)["shown"] == _expected(bu, k)
    again = _pixels(browser.screenshot())
    assert _same(_figure(browser, again), _figure(browser, at_k))
    # no request left the page: the only one is the file itself
    asked = browser.requests()
    assert asked and all(u.split("#")[0] in (url, "about:blank") for u in asked), asked


def test_the_animated_svg_plays_every_step_in_the_browser(browser, tmp_path):
    """Chromium's own SMIL engine, paused and set to the middle of each step's slot, shows that step."""
    bu = S.build("press", "velocity-plan")
    n, seconds = len(bu), 2.0
    path = tmp_path / "plan.svg"
    path.write_text(R.animated_svg(bu, seconds=seconds), encoding="utf-8")
    browser.events.clear()
    browser.open(path.as_uri())
    shown_at = ("(t => { const svg = document.documentElement; svg.pauseAnimations(); svg.setCurrentTime(t); "
                "return Array.from(document.querySelectorAll('g[data-step]'))"
                ".filter(g => getComputedStyle(g).visibility === 'visible').map(g => g.id); })")
    for k in range(1, n + 1):
        assert browser.evaluate(f"{shown_at}({(k - 0.5) * seconds})") == _expected(bu, k)
    # the cycle loops: one period later the first step shows again
    assert browser.evaluate(f"{shown_at}({n * seconds + 0.5 * seconds})") == ["new-1"]
    shot = browser.screenshot()
    (_shots_dir(tmp_path) / "animated_plan_step1.png").write_bytes(shot)
    assert _red(_pixels(shot)) > 50
    asked = browser.requests()
    assert all(u == path.as_uri() for u in asked), asked
