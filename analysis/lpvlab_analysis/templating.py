"""The Jinja2 environment of the report's HTML (templates/): autoescaped, so every value is text
unless marked safe; one environment for the page (report.py) and the tables (html_table.py).
The filter `scrolling` marks an HTML fragment safe with each of its tables in a box that scrolls
sideways, so no table widens the page."""
import functools
import os

import jinja2
import markupsafe


def scrolling_tables(fragment):
    """Every table of `fragment` in a box of its own that scrolls sideways."""
    return str(fragment).replace("<table", "<div class='scroll'><table").replace("</table>", "</table></div>")


@functools.lru_cache(maxsize=None)
def environment():
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(os.path.join(os.path.dirname(__file__), "templates")),
                             autoescape=True, undefined=jinja2.StrictUndefined, keep_trailing_newline=True)
    env.filters["scrolling"] = lambda fragment: markupsafe.Markup(scrolling_tables(fragment))
    return env


def render(template, **context):
    """templates/<template> filled with `context`, as markup (safe to put into another template)."""
    return markupsafe.Markup(environment().get_template(template).render(**context))
