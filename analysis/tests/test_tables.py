"""Ablation table: sorting and bold best values per metric column."""
import os
import tempfile
import unittest

from lpvlab_analysis import summary as S, tables


def _agg(text):
    d = tempfile.mkdtemp()
    p = os.path.join(d, "s.csv")
    with open(p, "w") as f:
        f.write(text)
    return S.aggregate(S.load_summary(p))


CSV = ("config_id,config_name,repeat,run_dir,param.propagation.type,time.total.ms,time.propagation.ms,memory_bytes,"
       "metric.indirect_vs_indirect1.rmse,metric.indirect_vs_indirect1.psnr\n"
       "a,slow,0,a,standard,9.0,5,1048576,0.1,30\n"
       "b,fast,0,b,standard,1.0,0.5,2097152,0.3,inf\n"
       "c,mid,0,c,occlusion,5.0,2,1048576,0.1,20\n")


class TablesTest(unittest.TestCase):
    def test_markdown_bold(self):
        md = tables.to_markdown(_agg(CSV)).strip().splitlines()
        self.assertEqual(len(md), 5)
        self.assertTrue(md[2].startswith("| fast |"))   # sorted by total time
        self.assertIn("**inf**", md[2])                  # highest PSNR (inf) is best
        self.assertNotIn("**0.3**", md[2])
        self.assertIn("**0.1**", md[3])                  # tie for lowest rmse: both bold
        self.assertIn("**0.1**", md[4])
        self.assertIn("| 2 |", md[2])                    # memory MB
        self.assertEqual(md[0].count("**"), 0)

    def test_html_bold(self):
        h = tables.to_html(_agg(CSV))
        self.assertEqual(h.count("<b>"), 3)
        self.assertIn("<b>inf</b>", h)

    def test_best_mask(self):
        self.assertEqual(tables.best_mask([3, float("nan"), 1, 1], False), [False, False, True, True])
        self.assertEqual(tables.best_mask([float("nan")], True), [False])


if __name__ == "__main__":
    unittest.main()
