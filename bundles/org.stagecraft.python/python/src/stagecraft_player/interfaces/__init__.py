"""One module per Player interface: its payload layouts and its proxy."""
