"""Hosting controllers: in this process (trusted) or in a sandboxed child."""
