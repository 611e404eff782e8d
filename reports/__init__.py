"""ballrace.reports."""
