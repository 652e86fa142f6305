"""Model-based controllers: linearisation at trim, discrete LQR, and the shared controller protocol."""
