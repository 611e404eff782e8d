"""ballrace.meshes."""
