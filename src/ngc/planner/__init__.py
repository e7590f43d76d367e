"""The cycle-time planner behind ``ngc time``."""
