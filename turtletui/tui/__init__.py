"""The Textual front end: the app, its screens and widgets.

``render`` is pure (numpy and Rich, no Textual) so it can be tested and
profiled without a terminal; ``widgets`` holds the Textual widgets.
"""
