"""Python drivers of the compiled kernels: the single and batched simulators, recording, statics and trim.
Imports ``model``, ``kernels`` and ``atmosphere``; knows no scene file, vehicle or environment."""
