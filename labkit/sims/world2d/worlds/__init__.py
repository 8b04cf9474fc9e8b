"""Worlds shipped with labkit (YAML files)."""
