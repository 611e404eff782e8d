"""ballrace.validation."""
