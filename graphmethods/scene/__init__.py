"""graphmethods.scene."""
