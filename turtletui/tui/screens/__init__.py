"""Screens shown over the app: the help and the lesson switcher."""
