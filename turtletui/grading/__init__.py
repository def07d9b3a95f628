"""Grading: run a lesson's scenarios, judge its checks, report the scores."""
