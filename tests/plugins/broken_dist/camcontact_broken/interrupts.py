"""A plugin that raises KeyboardInterrupt itself when it is imported (no Ctrl-C was pressed)."""

raise KeyboardInterrupt
