"""The former hand-written classes of the four classic kinds (slider-crank, four-bar, slotted lever,
shaper) with their base, as they were when the kinds moved onto the Assur-group core: closed-form
geometry, extreme positions and velocity plans written by hand for each kind. They are no part of
the package any more; tests/test_classic_presets.py checks the core's presets against them."""
from classic_reference.four_bar import FourBar
from classic_reference.shaper import Shaper
from classic_reference.slider_crank import SliderCrank
from classic_reference.slotted_lever import SlottedLever

__all__ = ["FourBar", "Shaper", "SliderCrank", "SlottedLever"]
