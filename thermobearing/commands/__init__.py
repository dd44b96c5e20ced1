"""Sub-commands of the ``thermobearing`` command (one module each; see :mod:`thermobearing.cli`)."""
