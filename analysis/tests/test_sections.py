"""The report's optional sections come from the modules that register them (sections.py), not
from one `if` per kind of run in report.py."""
import os
import unittest

import pandas as pd

import lpvlab_analysis
from lpvlab_analysis import sections as SC


class SectionsTest(unittest.TestCase):
    def test_every_module_registers_its_section_in_order(self):
        titles = [s.title for s in SC.report_modules(lpvlab_analysis)]
        self.assertEqual(titles[:5], ["Methods", "Convergence", "Bias over seeds", "Radiosity", "Particles"])

    def test_only_the_sections_and_parts_that_apply_are_written(self):
        empty = lambda *a: None  # noqa: E731
        part = lambda name, applies=None: SC.Part("n", empty, empty, empty, name + ".png", name + ".md",  # noqa: E731
                                                  applies)
        yes = SC.Section("Yes", lambda agg: True, [part("a"), part("b", lambda agg: False)])
        no = SC.Section("No", lambda agg: False, [part("c")])
        chosen = SC.applicable([yes, no], pd.DataFrame())
        self.assertEqual([(s.title, [p.image for p in parts]) for s, parts in chosen], [("Yes", ["a.png"])])

    def test_a_title_registered_twice_is_refused(self):
        with self.assertRaises(ValueError):
            SC.register(SC.Section("Methods", lambda agg: False, []))

    def test_report_names_no_kind_of_run(self):
        source = open(os.path.join(os.path.dirname(lpvlab_analysis.__file__), "report.py")).read()
        for module in ("methods", "radiosity", "particles"):
            self.assertNotIn(f"import {module}", source)
            self.assertNotIn(f"{module}.has_", source)


if __name__ == "__main__":
    unittest.main()
