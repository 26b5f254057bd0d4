"""graphmethods.render."""
