"""Chapter 04: the runner's barriers of one frame, both ways to the swapchain
image; drawn by 03_frame_barriers.py, whose docstring says what it shows."""

import importlib

importlib.import_module("03_frame_barriers").main(runner=True)
