"""Layer 2: names, --ros-args, the in-process middleware and the world clock."""
