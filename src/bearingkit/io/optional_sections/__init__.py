"""Schemas of the optional sections of a bearing file, beside the core schema (``io.schema``).

``cycle``: ``[[duty_cycle]]`` and ``[[tolerances]]``; ``operating``: ``[operating]``, ``[fits]``,
``[lubrication]``, ``[thermal]`` and the file model that holds them; ``structure``: ``[structure]`` (the
bearing's rings in their housing, docs/structure.md). Each validates its section with pydantic and
says what is wrong in one line; the loader (``io.loader``) reads them.
"""
