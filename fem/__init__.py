"""ballrace.fem."""
