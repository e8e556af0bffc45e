"""Built-in scenes (TOML data files)."""
