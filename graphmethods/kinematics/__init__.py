"""graphmethods.kinematics."""
