"""Lifting surfaces: geometry, vortex lattice, drag build-up."""
