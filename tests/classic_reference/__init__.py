"""The former hand-written classes of the four classic kinds, kept as the oracle for tests/test_classic_presets.py."""
from graphmethods.kinematics.four_bar import FourBar
from graphmethods.kinematics.shaper import Shaper
from graphmethods.kinematics.slider_crank import SliderCrank
from graphmethods.kinematics.slotted_lever import SlottedLever

__all__ = ["FourBar", "Shaper", "SliderCrank", "SlottedLever"]
