"""The report's sections for kinds of run that only some sweeps hold (other methods, radiosity,
particles, ...). The module that knows a kind of run registers its section here when it is
imported; report.py imports every module of the package (report_modules) and writes, in order,
each section whose `applies` holds for the sweep. A new kind of run is its module with one
`register(Section(...))`: no `if` for it in report.py."""

import importlib
import pkgutil
from typing import Callable, List, NamedTuple, Optional


class Part(NamedTuple):
    """One plot-and-table of a section: the note above it, and what draws and tabulates it."""
    note: str
    plot: Callable          # (agg, path, metric) -> the PNG's path, or None when nothing to draw
    html: Callable          # (agg, metric) -> an HTML table
    markdown: Callable      # (agg, metric) -> the same table as Markdown
    image: str              # the PNG's file name under img/
    markdown_file: str      # the Markdown's file name beside the report
    applies: Optional[Callable] = None  # (agg) -> bool; None: whenever the section applies


class Section(NamedTuple):
    title: str
    applies: Callable       # (agg) -> bool: the sweep holds this kind of run
    parts: List[Part]
    order: int = 50         # sections are written by order, then title


_REGISTRY: List[Section] = []


def register(section):
    if any(s.title == section.title for s in _REGISTRY):
        raise ValueError(f"report section '{section.title}' registered twice")
    _REGISTRY.append(section)
    return section


def report_modules(package):
    """Imports every module of `package` (so that each registers its sections) and returns the
    registered sections in order."""
    for module in pkgutil.iter_modules(package.__path__):
        importlib.import_module(f"{package.__name__}.{module.name}")
    return sorted(_REGISTRY, key=lambda s: (s.order, s.title))


def applicable(sections, agg):
    """The sections, each with its parts, that apply to this sweep's configurations."""
    out = []
    for section in sections:
        if section.applies(agg):
            parts = [p for p in section.parts if p.applies is None or p.applies(agg)]
            out.append((section, parts))
    return out
