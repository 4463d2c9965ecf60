"""Contact mechanics: geometry, Hertz line and elliptical contact, subsurface stresses, roughness."""
