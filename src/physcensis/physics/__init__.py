"""Physics: MuJoCo model building from assets and supports (no predicates, no solver logic)."""
