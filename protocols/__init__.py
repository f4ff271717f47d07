"""Everything that crosses a wire, described once and used in both directions."""
