"""The report's HTML tables, from templates/table.html.j2 (autoescaped): every table a section
hands the page is drawn by this one template, with a header row (sortable by a click, the page's
script) and cells that may be numbers (right-aligned) or bold (the best or winning values)."""
from . import templating


def header(text, title=None, arrow=""):
    """A column heading; `title` shows on hover, `arrow` ("up"/"down") says which way is better."""
    return {"text": text, "title": title, "arrow": arrow}


def cell(text, bold=False, num=False):
    return {"text": text, "bold": bold, "num": num}


def render(headers, rows, css_class=None):
    """`headers`: strings or header(); `rows`: lists of strings or cell()."""
    heads = [h if isinstance(h, dict) else header(h) for h in headers]
    body = [[c if isinstance(c, dict) else cell(c) for c in row] for row in rows]
    return templating.render("table.html.j2", headers=heads, rows=body, css_class=css_class)
