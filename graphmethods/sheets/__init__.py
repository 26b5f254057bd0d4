"""graphmethods.sheets."""
