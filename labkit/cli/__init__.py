"""Layer 7: the `ros2` verbs, the IPython magics and the `labkit` console command."""
