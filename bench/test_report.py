# SPDX-License-Identifier: LGPL-3.0-or-later
"""Unit checks of the report, plot and profile code of bench/ on small synthetic raw data (no
measurement): the tables, the readings' figures, missing rows, seeds' spreads, profile categories.
Run: python3 -m unittest discover -s bench -p test_report.py (ctest: bench_report_unit)."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
import fragment_births  # noqa: E402
import perf_profile  # noqa: E402
import report  # noqa: E402

CFG = {"repeats": 1, "time_cap": 30, "gmpq_max": 1000, "control_max": 20000, "order_samples": 100,
       "exact_order_samples": 50, "corpus_cad": ["part", "blade"], "corpus_organic": ["elephant"],
       "heuristic_repeats": 1, "corpus_cap": 60, "min_split_max": 6000, "naive_random_max": 20000}


def build_row(mesh, kernel, seconds, fragments, status="ok", heuristic="sampled", label="accuracy", **extra):
    r = {"label": label, "input": mesh, "kernel": kernel, "heuristic": heuristic, "status": status, "triangles": 100,
         "time_cap": 30, "seed": 0}
    if status == "ok":
        r.update({"fragments": fragments, "splits": fragments - 100, "depth": 10, "build_seconds_median": seconds,
                  "cpu_seconds_median": seconds, "peak_heap_bytes": 1 << 20, "peak_heap_bytes_per_fragment": 900,
                  "counted_build_seconds": seconds})
    r.update(extra)
    return r


def defects(fragments, off, mis, errors, pairs):
    return {"fragments": fragments, "non_finite": 0, "off_plane": off, "split_sources": 10, "not_tiling": 3,
            "misclassified": mis, "eyes": 4, "occluding_pairs": pairs, "order_errors": errors, "seconds": 0.5}


ACCURACY = [
    build_row("part", "double", 0.01, 200, defects=defects(200, 150, 100, 10, 1000)),
    build_row("part", "epick", 0.02, 150, defects=defects(150, 100, 50, 2, 1000)),
    build_row("part", "exact", 0.015, 120),
    build_row("part", "epeck", 0.04, 120, defects=defects(120, 0, 0, 0, 500)),
    build_row("blade", "double", None, None, status="limit"),
    build_row("blade", "exact", 0.3, 1100),
    build_row("elephant", "double", 0.1, 900),
    build_row("elephant", "exact", 0.3, 700),
]


class Formatting(unittest.TestCase):
    def test_numbers(self):
        self.assertEqual(report.fmt_int(1234567), "1 234 567")
        self.assertEqual(report.fmt_s(0.0123), "12.3 ms")
        self.assertEqual(report.fmt_s(None), "—")
        self.assertEqual(report.fmt_range((5, 5, 5)), "5")
        self.assertEqual(report.fmt_range((1540, 1502, 1598)), "1 540 (1 502–1 598)")

    def test_missing_rows_say_why(self):
        self.assertEqual(report.status_cell(build_row("blade", "double", None, None, status="limit")),
                         "> 4M fragments (stopped)")
        self.assertEqual(report.status_cell(build_row("x", "gmpq", None, None, status="timeout")), "> 30 s")
        self.assertIsNone(report.status_cell(ACCURACY[0]))

    def test_statistics(self):
        self.assertEqual(common.median([3, 1, 2]), 2)
        self.assertEqual(common.median([4, 1, 3, 2]), 2.5)
        self.assertAlmostEqual(common.slope([10, 100, 1000], [1, 100, 10000]), 2.0)
        self.assertIsNone(common.slope([10, 100], [1, 2]))
        rows = [{"fragments": f} for f in (30, 10, 20)]
        self.assertEqual(common.spread(rows, "fragments"), (20, 10, 30))


class Accuracy(unittest.TestCase):
    def test_the_default_kernel_is_the_goal(self):
        text, summary = report.section_accuracy(ACCURACY, CFG, "plots")
        self.assertIn("within 1.5× of the double build", text)
        self.assertIn("`exact`", text)
        # part: exact 1.5x, blade: double stopped, so only part counts on CAD.
        self.assertEqual(summary["cad_count"], 1)
        self.assertAlmostEqual(summary["cad_median"], 1.5)
        self.assertIn("| blade | CAD | 100 | double | > 4M fragments (stopped) |", text)
        self.assertIn("Epeck, the same tree with CGAL's lazy kernel: median 4.00×", text)

    def test_defects_are_shares_of_pairs_and_fragments(self):
        text, _ = report.section_accuracy(ACCURACY, CFG, "plots")
        self.assertIn("| part | double | 200 | 0 | 150 | 3 / 10 | 100 | 10 / 1 000 | 0.50 s |", text)
        self.assertIn("double: 75% of fragments off their plane, 50% misclassified, 0 non-finite, "
                      "10 order errors in 1 000 occluding pairs (1.00%)", text)
        self.assertIn("The Epeck control: 0 defects in 120 fragments", text)


class Heuristics(unittest.TestCase):
    def rows(self):
        out = []
        for seed, frags in [(0, 1540), (1, 1502), (2, 1598)]:
            for n, scale in [(250, 1), (500, 2), (1000, 4)]:
                out.append(build_row(f"soup-{n}", "exact", 0.01 * scale, frags * scale, heuristic="naive",
                                     label="soup", triangles=n, seed=seed))
        return out

    def test_cells_show_the_median_and_the_spread_over_seeds(self):
        rows = [r for r in self.rows() if r["triangles"] == 250]
        self.assertEqual(report.heuristic_cell(rows), "1 540 (1 502–1 598) / 10 / 10.0 ms")
        self.assertEqual(report.heuristic_cell([]), "—")

    def test_slopes_fit_the_medians(self):
        xs, sf, st, sd = report.heuristic_slopes(self.rows())["naive"]
        self.assertEqual(xs, [250, 500, 1000])
        self.assertAlmostEqual(sf, 1.0)
        self.assertAlmostEqual(sd, 0.0)

    def test_section_names_the_seeds_and_the_kernel(self):
        text, _ = report.section_heuristics(self.rows(), [], [], ACCURACY, CFG, "plots")
        self.assertIn("3 seeds (0, 1, 2)", text)
        self.assertIn("(`exact` kernel)", text)


class Profile(unittest.TestCase):
    def test_categories_come_from_objects_and_namespaces(self):
        c = perf_profile.category
        self.assertEqual(c("libgmp.so.10.4.1", "__gmpz_mul"), perf_profile.CATEGORIES[0])
        self.assertEqual(c("libc.so.6", "_int_free"), perf_profile.CATEGORIES[2])
        self.assertEqual(c("bench_sweep", "void exbsp::basic_bsp_tree<exbsp::exact_geometry>::grow_node<"
                                          "exbsp::basic_bsp_tree<exbsp::exact_geometry>::x>(int)"), "exbsp")
        self.assertEqual(c("bench_sweep", "CGAL::Sign CGAL::Static_filtered_predicate<A, B>::operator()<P>(P const&)"),
                         perf_profile.CATEGORIES[4])
        self.assertEqual(c("bench_sweep", "std::vector<int>::_M_realloc_insert(int&&)"), perf_profile.CATEGORIES[6])

    def test_report_parsing(self):
        text = ("# comment\n 12.50%  ;libgmp.so.10.4.1    ;[.] __gmpz_mul\n"
                "  7.25%  ;bench_sweep         ;[.] exbsp::split(int)\n")
        rows = perf_profile.parse_report(text)
        self.assertEqual(rows, [{"percent": 12.5, "dso": "libgmp.so.10.4.1", "function": "__gmpz_mul"},
                                {"percent": 7.25, "dso": "bench_sweep", "function": "exbsp::split(int)"}])
        cats = perf_profile.categorize(rows)
        self.assertAlmostEqual(sum(cats.values()), 19.75)

    def test_section_reads_the_default_kernel(self):
        rows = perf_profile.parse_report(" 40.00%  ;bench_sweep ;[.] exbsp::f()\n 60.00%  ;libgmp.so.10 ;[.] __gmpz_mul\n")
        prof = {"mesh": "joint", "exact": {"rows": rows, "categories": perf_profile.categorize(rows)}}
        text = report.section_profile(prof)
        self.assertIn("spends 40% of its time in exbsp's own code, 60% in rational arithmetic", text)
        self.assertIn("perf did not run", report.section_profile({"mesh": "joint", "exact": {"error": "no perf"}}))


STACKED = [build_row("stacked_1000", "exact", 12.0, 1000, label="stacked", heuristic="naive", triangles=1000),
           build_row("stacked_1000", "epeck", None, None, status="time_cap", label="stacked", heuristic="naive",
                     triangles=1000)]
PEERS = [{"tool": "csg.js", "version": "1.0.1", "mesh": "/x/part.off", "build_seconds": 0.01,
          "pieces_triangulated": 300},
         {"tool": "csg.js", "version": "1.0.1", "mesh": "/x/blade.off", "build_seconds": 0.6,
          "pieces_triangulated": 2000},
         {"tool": "jscad", "version": "2.13.0", "mesh": "/x/part.off", "error": "out of memory"}]


class Goals(unittest.TestCase):
    def test_goal_table_states_issue_10s_goals(self):
        _, acc_sum = report.section_accuracy(ACCURACY, CFG, "plots")
        text = report.goals_table(acc_sum, {}, ACCURACY, STACKED, PEERS)
        self.assertIn("median 1.50× wall", text)
        self.assertIn("| … and worst ≤ 2.0× | 1.50× (part) | met |", text)
        self.assertIn("median 900 B, largest 900 B", text)
        self.assertIn("| naive on 1 000 stacked triangles (depth 1 000), `exact`: under 60 s | 12.0 s", text)
        # csg.js: part 0.01 s < exact 0.015 s (exbsp slower), blade 0.6 s > 0.3 s.
        self.assertIn("| `exact` builds faster than csg.js on every CAD mesh | 1 of 2 (slower on part) | not met |",
                      text)
        self.assertNotIn("faster than jscad", text)  # jscad has no time on any mesh

    def test_per_mesh_table_and_peers_section(self):
        per_mesh = report.goals_per_mesh(ACCURACY, PEERS)
        self.assertIn("| part | 15.0 ms | 10.0 ms | 1.50× | 900 | 0.67× | — |", per_mesh)
        text = report.section_peers(ACCURACY, PEERS, "v18", "plots")
        self.assertIn("Node v18", text)
        self.assertIn("out of memory", text)
        self.assertIn("Skipped in this run", report.section_peers(ACCURACY, [], "", "plots"))


class WholeReport(unittest.TestCase):
    @staticmethod
    def inputs():
        """(meta, data) of a small report."""
        meta = {"quick": True, "minutes": 1, "cpu": "cpu", "nproc": "2", "memory_gib": 1, "kernel": "Linux",
                "compiler": "c++", "cgal": "5.5", "load_start": [1, 1, 1], "load_end": [2, 2, 2], "commit": "abc",
                "dirty": False, "date": "today"}
        data = {"accuracy": ACCURACY, "soup": Heuristics().rows(), "sticks": [], "corpus": [], "render": [],
                "micro": None, "profile": {}, "stacked": STACKED, "peers": PEERS, "node": "v18"}
        return meta, data

    def test_write_and_plot(self):
        meta, data = self.inputs()
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "RESULTS.md")
            report.write(path, meta, CFG, data, "plots", "bench/run.py --quick")
            with open(path) as f:
                text = f.read()
            self.assertIn("## Goals: where we stand", text)
            self.assertIn("| `exact` build / `double` build, same heuristic (sampled), CAD corpus: median ≤ 1.5×", text)
            self.assertIn("## 6. Peers", text)
            try:
                import matplotlib  # noqa: F401
            except ImportError:
                self.skipTest("matplotlib missing")
            import plots
            plots.draw_all(data, CFG, os.path.join(d, "plots"))
            self.assertEqual(sorted(os.listdir(os.path.join(d, "plots"))),
                             ["accuracy_defects.png", "accuracy_ratio.png", "heuristics_corpus.png",
                              "heuristics_soup.png", "peers.png"])

    def test_sections_of_other_scripts_are_kept(self):
        meta, data = self.inputs()
        blocks = ["<!-- hidden-lines:begin -->\n## 7. lines\n<!-- hidden-lines:end -->",
                  "<!-- assemblies:begin -->\n## 9. big\n<!-- assemblies:end -->",
                  "<!-- births:begin -->\n## 10. births\n<!-- births:end -->"]
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "RESULTS.md")
            with open(path, "w") as f:
                f.write("old text\n\n" + "\n\nbetween\n\n".join(blocks) + "\n")
            report.write(path, meta, CFG, data, "plots", "bench/run.py --quick")
            with open(path) as f:
                text = f.read()
        self.assertNotIn("old text", text)
        self.assertNotIn("between", text)
        at = [text.index(b) for b in blocks]
        self.assertEqual(at, sorted(at))
        self.assertEqual(text.count("<!-- births:begin -->"), 1)


class Births(unittest.TestCase):
    """bench/fragment_births.py's exact plane classes and its location of split events."""

    def test_plane_classes_are_exact(self):
        import math
        v = [[0.1, 0.2, 0.3], [1.1, 0.2, 0.3], [1.1, 1.2, 0.3], [0.1, 1.2, 0.3],
             [0.1, 0.2, math.nextafter(0.3, 1.0)], [2.0, 2.0, 2.0], [3.0, 3.0, 3.0]]
        t = [(0, 1, 2), (0, 2, 3), (2, 1, 0), (4, 1, 2), (1, 5, 6), (5, 6, 5)]
        c = fragment_births.plane_classes(v, t)
        self.assertEqual(c[0], c[1])  # the two halves of a square
        self.assertEqual(c[0], c[2])  # either orientation
        self.assertNotEqual(c[0], c[3])  # one corner one ulp above the square's plane
        self.assertEqual(len({c[3], c[4], c[5]}), 3)  # a slanted plane, a degenerate triangle

    def test_located_events_and_their_causes(self):
        # faces 0..9; parts: faces 0-7 part 0, 8-9 part 1; file planes: 1, 2 and 4 are one plane.
        part_of = [0] * 8 + [1] * 2
        plane_key = [(p, c) for p, c in zip(part_of, [10, 11, 11, 13, 11, 15, 16, 17, 18, 19])]
        paths = [
            (0, [(8, 1)]), (0, [(8, -1)]),  # another part's plane: parts meet, depth 1
            (1, [(8, 1), (2, 1)]), (1, [(8, 1), (2, -1)]),  # its file plane: coplanar, depth 2
            (3, [(8, 1), (2, 1), (4, 1)]), (3, [(8, 1), (2, 1), (4, -1)]),  # plane 2 again: depth 3
            (6, [(7, -1)]), (6, [(7, 1)]), (6, [(7, 1)]),  # own shape at depth 1, one event
            (5, [(7, 1), (9, -1)]), (5, [(7, 1), (9, -1)]),  # two pieces never parted: none
        ]
        events = fragment_births.located_events(paths, plane_key, part_of)
        self.assertEqual(dict(events), {("parts meet", 1): 1, ("placement: coplanar", 2): 1,
                                        ("placement: plane again", 3): 1, ("own shape", 1): 1})


if __name__ == "__main__":
    unittest.main()
