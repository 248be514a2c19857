#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Hidden-line drawings of CGAL meshes: exbsp against Open CASCADE's hidden-line removal (HLR) as
FreeCAD exposes it, both judged by the same independent ray-cast oracle
(tests/support/hidden_line_oracle.h). Issue 23, "peers table". Writes bench/hlr_peers.md (and
prints it); raw JSON per mesh and view in build/hlr_peers/ (or --work-dir).

    bench/hlr_peers.py                          meshes and views below, build/bench/hlr_judge
    bench/hlr_peers.py --meshes cube joint --views front isometric
    bench/hlr_peers.py --build-dir build --repeats 3 --out bench/hlr_peers.md

Needs build/bench/hlr_judge (`cmake --build build --target hlr_judge`, a build with
EXBSP_BUILD_TESTS and EXBSP_BUILD_BENCH) and FreeCAD's Python modules (Debian:
`apt-get install --no-install-recommends freecad-python3`, modules in
/usr/lib/freecad-python3/lib). Without FreeCAD it prints why and exits 0 ("skipped").

Per mesh and PARALLEL view (front, top, right, isometric: the directions and view-up vectors of
tests/test_hidden_lines.cpp; isometric looks along (-1, -1, -1), from the (+, +, +) corner), at
400 x 300 pixels:

  exbsp  bench/hlr_judge builds the frame of the hidden-line tests (the camera 4 radii from
         the bounding box's centre, an orthographic window of 1.3 radii, edges
         "visible+hidden", crease 30 degrees), runs the SVG pipeline once and times, in that
         process, add_edge_paths (feature edges + exact visibility + edge paths: the
         hidden-line drawing; best of --repeats): the "exbsp s" column. The whole SVG pipeline
         (BSP build + order + transform+clip + svg, run once) is in the second table.
  OCCT   the same mesh as a B-rep solid: Mesh.Mesh(file) -> Part.Shape().makeShapeFromMesh(
         mesh.Topology, tolerance) (one planar face per triangle, sewn) -> Part.Solid(
         Part.Shell(faces)) -> removeSplitter() (coplanar neighbouring faces merged into one
         face: a cube becomes 6 faces and 12 edges; a tessellated curved surface keeps its
         facets, so every edge between two facets that are not coplanar stays an edge, however
         small its angle). The solid is moved rigidly into the view's camera frame (right, up,
         toward the viewer as x, y, z; the look-at point at the origin), so that
         Drawing.projectEx(solid, (0, 0, 1)) -- HLRBRep_Algo with the projector
         gp_Ax2((0, 0, 0), (0, 0, 1)), whose x axis is (1, 0, 0): Add, Update, Hide, then the ten
         HLRBRep_HLRToShape compounds -- returns the drawing in that frame's x, y. The timed call
         is projectEx alone (best of --repeats, but once when it takes more than 5 s); reading
         the mesh and making the solid are reported apart. (Part.HLRBRep.Algo.setProjector would
         take the x axis directly but its argument parsing is broken in FreeCAD 0.20.2:
         "more argument specifiers than keyword list entries".)
         Compounds -> the contract's feature edges: visible = V (visible sharp edges, C0:
         every edge between two non-coplanar faces) + V1 (visible smooth, G1) + VO (visible
         outlines: silhouettes of curved faces; none on planar faces, where the silhouette is a
         sharp edge); hidden = H + H1 + HO likewise. Left out: VN/HN (sewn, C2 "edges" inside
         a smooth surface: no feature) and VI/HI (isolines: none asked for, nbIso = 0).
         The 2D edges (lines; other curves discretized to 1/10 pixel) are mapped to the
         drawing grid with the view's exact mapping from hlr_judge (--mapping-only: the
         oracle's own projection, an affine map; 1/100 pixel, y up, origin at the viewport's
         lower-left) and written as the peer's JSON; hlr_judge --peer judges them with the
         same oracle instance that judges exbsp's drawing, in the same run.
  OCCT, feature-edge strokes only: the same OCCT drawing (same call, same time) with its
         strokes kept only where they lie on the projection of a solid edge that the contract
         calls a feature edge in this view (crease: outward face normals more than 30 degrees
         apart; silhouette: one face towards the viewer, the other not; boundary). A filter of
         ours, not part of OCCT: it separates OCCT's visibility (what this column judges) from
         its choice of edges (every edge between non-coplanar faces, which the first OCCT
         column's run check counts as "spurious" where no feature edge is).

The oracle: samples along its own feature edges (boundary, non-manifold, crease > 30 degrees,
silhouette), each decided by exact ray casting; "samples" = the share of checked samples drawn
right (solid where visible, dashed where hidden); "runs" = the share of points along the drawn
runs that lie on a feature edge with that visibility (a stroke where no feature edge is, e.g.
an OCCT facet edge of a 10-degree crease, counts as "spurious"; a dashed stroke under a visible
one as "dashed under visible": OCCT does not remove superimposed lines).
"""
import argparse
import json
import math
import os
import platform
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
MESHES = os.path.join(REPO, "data", "meshes")

# Cube-like parts first (cube: 12 triangles; cube-meshed: the same cube, 1728 triangles; corner:
# an L-shaped block of quads; cross: a flat cross), then the CGAL CAD meshes of the hidden-line
# tests.
DEFAULT_MESHES = ["cube", "cube-meshed", "corner", "cross", "joint", "couplingdown", "pinion"]
DEFAULT_VIEWS = ["front", "top", "right", "isometric"]
WIDTH, HEIGHT = 400, 300
CREASE_DEG = 30  # the contract's crease angle (hlr_judge's default)

FREECAD_LIB_CANDIDATES = ["/usr/lib/freecad-python3/lib", "/usr/lib/freecad/lib",
                          "/usr/local/lib/freecad-python3/lib", "/usr/share/freecad/lib"]

# projectEx's ten compounds, in its order, and what each means to the contract.
PROJECT_EX = ["V", "V1", "VN", "VO", "VI", "H", "H1", "HN", "HO", "HI"]
VISIBLE_COMPOUNDS = ["V", "V1", "VO"]  # sharp, smooth, outline
HIDDEN_COMPOUNDS = ["H", "H1", "HO"]


def log(msg):
    print(f"[hlr_peers {time.strftime('%H:%M:%S')}] {msg}", file=sys.stderr, flush=True)


def import_freecad():
    """FreeCAD's modules, or None (with the reason) when they cannot be imported."""
    extra = os.environ.get("FREECAD_LIB")
    for d in ([extra] if extra else []) + FREECAD_LIB_CANDIDATES:
        if d and os.path.isdir(d) and d not in sys.path:
            sys.path.append(d)
    try:
        import FreeCAD  # noqa: F401
        import Mesh  # noqa: F401
        import Part  # noqa: F401
        import Drawing  # noqa: F401
    except Exception as e:  # ImportError, or a shared library of another Python
        return None, f"{type(e).__name__}: {e}"
    import FreeCAD
    import Drawing
    import Mesh
    import Part
    return (FreeCAD, Mesh, Part, Drawing), None


def machine_notes():
    cpu = ""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return {"nproc": os.cpu_count(), "cpu": cpu or platform.processor(),
            "python": platform.python_version()}


def loadavg():
    try:
        return " ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:
        return "?"


def hlr_judge(judge, mesh_path, view, *extra):
    cmd = [judge, mesh_path, "--view", view, "--size", f"{WIDTH}x{HEIGHT}", *extra]
    log(" ".join(cmd))
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def mesh_to_solid(fc, mesh_path):
    """The mesh as an OCCT solid (module docstring); returns (solid, info)."""
    FreeCAD, Mesh, Part, _ = fc
    t0 = time.perf_counter()
    mesh = Mesh.Mesh(mesh_path)
    bb = mesh.BoundBox
    tolerance = 1e-7 * max(bb.DiagonalLength, 1e-300)  # sewing: the OFF shares its vertices
    shape = Part.Shape()
    shape.makeShapeFromMesh(mesh.Topology, tolerance)
    faces_in = len(shape.Faces)
    try:
        solid = Part.Solid(Part.Shell(shape.Faces))
        kind = "solid"
    except Exception as e:  # not closed: keep the shell
        log(f"{os.path.basename(mesh_path)}: no solid ({e}); using the shell")
        solid, kind = Part.Shell(shape.Faces), "shell"
    t1 = time.perf_counter()
    refined = solid.removeSplitter()
    t2 = time.perf_counter()
    info = {"mesh_facets": mesh.CountFacets, "faces_before": faces_in, "kind": kind,
            "faces": len(refined.Faces), "edges": len(refined.Edges), "valid": refined.isValid(),
            "seconds_solid": t1 - t0, "seconds_remove_splitter": t2 - t1}
    return refined, info


def in_camera_frame(fc, solid, mapping):
    """A copy of `solid` moved rigidly: right, up, toward-viewer -> x, y, z; look_at -> 0."""
    FreeCAD = fc[0]
    r, u, w, c = mapping["right"], mapping["up"], mapping["toward_viewer"], mapping["look_at"]
    m = FreeCAD.Matrix()
    for i, row in enumerate((r, u, w)):
        for j in range(3):
            setattr(m, f"A{i + 1}{j + 1}", row[j])
        setattr(m, f"A{i + 1}4", -sum(row[k] * c[k] for k in range(3)))
    moved = solid.copy()
    moved.transformShape(m, True)
    return moved


def occt_hlr(fc, moved, repeats):
    """Drawing.projectEx along +z of the camera frame: (compounds by name, best seconds, runs)."""
    FreeCAD, _, _, Drawing = fc
    best, runs, result = float("inf"), 0, None
    while runs < max(1, repeats):
        t0 = time.perf_counter()
        result = Drawing.projectEx(moved, FreeCAD.Vector(0, 0, 1))
        dt = time.perf_counter() - t0
        best, runs = min(best, dt), runs + 1
        if dt > 5:
            break
    return dict(zip(PROJECT_EX, result)), best, runs


def edges_of(shape):
    try:
        return list(shape.Edges) if shape is not None and not shape.isNull() else []
    except Exception:
        return []


def to_grid_polylines(edges, mapping):
    """OCCT's 2D edges (x, y in the camera frame) as flat grid polylines [x0, y0, x1, y1, ...]."""
    G = mapping["grid_from_world"]
    r, u, c = mapping["right"], mapping["up"], mapping["look_at"]
    # grid = G (c + x r + y u, 1): affine in (x, y).
    base = [sum(G[i][k] * c[k] for k in range(3)) + G[i][3] for i in range(2)]
    gx = [sum(G[i][k] * r[k] for k in range(3)) for i in range(2)]
    gy = [sum(G[i][k] * u[k] for k in range(3)) for i in range(2)]
    deflection = 0.1 * 100 / mapping["scale"]  # 1/10 pixel in world units
    lines, curves = [], 0
    for e in edges:
        try:
            straight = type(e.Curve).__name__ in ("Line", "LineSegment")
        except Exception:
            straight = False
        if straight:
            pts = [e.valueAt(e.FirstParameter), e.valueAt(e.LastParameter)]
        else:
            curves += 1
            pts = e.discretize(Deflection=deflection)
        flat = []
        for p in pts:
            flat += [base[0] + p.x * gx[0] + p.y * gy[0], base[1] + p.x * gx[1] + p.y * gy[1]]
        if len(flat) >= 4:
            lines.append(flat)
    return lines, curves


def contract_edges_2d(fc, moved, crease_deg):
    """The straight edges of `moved` (the solid in the camera frame) projected to its x, y, each
    with whether the contract calls it a feature edge in this view: boundary or non-manifold
    (not two faces), crease (the angle between the two faces' outward normals exceeds
    crease_deg) or silhouette (one face turned towards the viewer, +z, the other not)."""
    Part = fc[2]
    cos_crease = math.cos(math.radians(crease_deg))
    normals = {}
    out = []
    for e in moved.Edges:
        v0, v1 = e.Vertexes[0].Point, e.Vertexes[-1].Point
        faces = moved.ancestorsOfType(e, Part.Face)
        if len(faces) != 2:
            feature = True
        else:
            n = []
            for f in faces:
                key = f.hashCode()
                if key not in normals:
                    u0, u1, w0, w1 = f.ParameterRange
                    normals[key] = f.normalAt((u0 + u1) / 2, (w0 + w1) / 2)  # outward (orientation)
                n.append(normals[key])
            crease = n[0].dot(n[1]) < cos_crease
            silhouette = (n[0].z > 0) != (n[1].z > 0)
            feature = crease or silhouette
        out.append(((v0.x, v0.y), (v1.x, v1.y), feature))
    return out


def keep_on_features(edges, solid_edges, eps):
    """OCCT's 2D edges kept where they lie on the projection of a feature edge of the solid
    (both ends within eps of it); an edge on no projected solid edge is kept too (counted)."""
    spans = [max(abs(b[0] - a[0]), abs(b[1] - a[1])) for a, b, _ in solid_edges]
    cell = max(sorted(spans)[len(spans) // 2] if spans else 1.0, 1e-9)
    grid = {}
    for i, (a, b, _) in enumerate(solid_edges):
        for gx in range(int(math.floor(min(a[0], b[0]) / cell)), int(math.floor(max(a[0], b[0]) / cell)) + 1):
            for gy in range(int(math.floor(min(a[1], b[1]) / cell)), int(math.floor(max(a[1], b[1]) / cell)) + 1):
                grid.setdefault((gx, gy), []).append(i)

    def on(p, a, b):
        dx, dy = b[0] - a[0], b[1] - a[1]
        L2 = dx * dx + dy * dy
        if L2 == 0:
            return False
        t = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L2
        L = math.sqrt(L2)
        if t < -eps / L or t > 1 + eps / L:
            return False
        return abs((p[0] - a[0]) * dy - (p[1] - a[1]) * dx) / L <= eps

    kept, dropped, unmatched = [], 0, 0
    for e in edges:
        p = e.valueAt(e.FirstParameter)
        q = e.valueAt(e.LastParameter)
        p, q = (p.x, p.y), (q.x, q.y)
        m = ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2)
        cands = grid.get((int(math.floor(m[0] / cell)), int(math.floor(m[1] / cell))), [])
        matches = [solid_edges[i][2] for i in cands
                   if on(p, *solid_edges[i][:2]) and on(q, *solid_edges[i][:2])]
        if not matches:
            unmatched += 1
            kept.append(e)
        elif any(matches):
            kept.append(e)
        else:
            dropped += 1
    return kept, dropped, unmatched


def pct(x):
    return f"{100 * x:.2f}%"


def secs(x):
    if x < 1e-3:
        return f"{x * 1e6:.0f} µs"
    return f"{x * 1e3:.2f} ms" if x < 1 else f"{x:.2f} s"


def agreement_cell(rep):
    return (f"{pct(rep['agreement'])} of {rep['samples']} / "
            f"{pct(rep['run_agreement'])} of {rep['run_points']}")


def write_table(rows, notes, out_path, args):
    L = []
    L.append("# Hidden-line drawing: exbsp against Open CASCADE's HLR (FreeCAD)")
    L.append("")
    L.append("Written by `bench/hlr_peers.py` (issue 23, \"peers table\"); rerun it to refresh. "
             "Both drawings of each row are judged by one instance of the ray-cast oracle "
             "(`tests/support/hidden_line_oracle.h`) through `bench/hlr_judge`, in parallel "
             f"views of {WIDTH} x {HEIGHT} pixels, crease angle 30 degrees. Agreement cells: "
             "samples along the oracle's feature edges drawn right / points along the drawn "
             "runs that are right (the oracle's run check). Times: exbsp = `add_edge_paths` "
             "(feature edges + exact visibility + edge paths), OCCT = `Drawing.projectEx` "
             "(HLRBRep_Algo: Add, Update, Hide, the ten result compounds); best of "
             f"{args.repeats} each (OCCT: once when a run takes over 5 s); ratio = OCCT / exbsp. "
             "How the meshes become OCCT solids and which compounds count as what: the "
             "docstring of `bench/hlr_peers.py`.")
    L.append("")
    L.append(f"Machine: {notes['nproc']} cores, {notes['cpu']}; FreeCAD {notes['freecad']}; "
             f"load average (1, 5, 15 min) before {notes['load_before']}, after "
             f"{notes['load_after']}; {notes['date']}.")
    L.append("")
    L.append("| mesh | view | triangles | exbsp agreement (samples / runs) | exbsp s | "
             "OCCT agreement (samples / runs) | OCCT s | OCCT / exbsp | "
             "OCCT, feature-edge strokes only (samples / runs) |")
    L.append("|---|---|---:|---|---:|---|---:|---:|---|")
    for r in rows:
        ex, pe = r["exbsp"], r.get("peer")
        if pe is None:
            L.append(f"| {r['mesh']} | {r['view']} | {r['triangles']} | {agreement_cell(ex)} | "
                     f"{secs(ex['seconds'])} | {r.get('error', 'failed')} | | | |")
            continue
        ratio = r["occt_seconds"] / ex["seconds"] if ex["seconds"] > 0 else float("inf")
        L.append(f"| {r['mesh']} | {r['view']} | {r['triangles']} | {agreement_cell(ex)} | "
                 f"{secs(ex['seconds'])} | {agreement_cell(pe)} | {secs(r['occt_seconds'])} | "
                 f"{ratio:.1f}x | {agreement_cell(r['peers'][1])} |")
    L.append("")
    L.append("Details. exbsp drawing = `visible_drawing` (visible regions + the edges; best of "
             f"{args.repeats}); exbsp pipeline = the whole SVG pipeline once (BSP build, order, "
             "transform+clip, svg with regions and edges). Wrong samples: visible drawn "
             "dashed or missing + hidden drawn solid or missing. Wrong run points: solid over "
             "hidden / dashed under visible / spurious (no feature edge there). OCCT solid = "
             "faces after removeSplitter (from one per triangle); OCCT strokes = visible + "
             "hidden 2D edges (edges of the solid split where their visibility changes); "
             "dropped = of these, the strokes the feature-edge filter left out (lying only on "
             "solid edges that are neither creases over 30 degrees nor silhouettes in the view).")
    L.append("")
    L.append("| mesh | view | feature edges | exbsp drawing s | exbsp pipeline s | "
             "exbsp wrong samples | "
             "exbsp wrong runs | OCCT wrong samples | OCCT wrong runs (solid/dashed/spurious) | "
             "OCCT solid faces | OCCT strokes (vis + hid) | dropped | "
             "filtered OCCT wrong samples | filtered OCCT wrong runs (solid/dashed/spurious) |")
    L.append("|---|---|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---|")
    for r in rows:
        ex, pe = r["exbsp"], r.get("peer")
        cells = [r["mesh"], r["view"], str(r["feature_edges"]), secs(ex["seconds_drawing"]),
                 secs(ex["seconds_pipeline"]),
                 str(ex["wrong"]), str(ex["run_wrong"])]
        if pe is None:
            cells += [""] * 7
        else:
            fp = r["peers"][1]
            dr = r["occt_filter"]["dropped"]
            cells += [str(pe["wrong"]),
                      f"{pe['run_wrong']} ({pe['solid_over_hidden']}/{pe['dashed_under_visible']}/"
                      f"{pe['spurious']})",
                      str(r["solid"]["faces"]),
                      f"{r['occt_edges']['visible']} + {r['occt_edges']['hidden']}",
                      str(dr["visible"] + dr["hidden"]),
                      str(fp["wrong"]),
                      f"{fp['run_wrong']} ({fp['solid_over_hidden']}/{fp['dashed_under_visible']}/"
                      f"{fp['spurious']})"]
        L.append("| " + " | ".join(cells) + " |")
    L.append("")
    L.append("The OCCT solids (per mesh, not timed with the HLR): mesh facets, faces and edges "
             "after removeSplitter, seconds to read the mesh and make the solid "
             "(makeShapeFromMesh + Part.Solid), seconds of removeSplitter. OCCT's HLR works on "
             "the merged faces, exbsp and the oracle on the triangles: cube-meshed is 1728 "
             "triangles to exbsp and 6 faces to OCCT.")
    L.append("")
    L.append("| mesh | facets | faces | edges | valid | make solid s | removeSplitter s |")
    L.append("|---|---:|---:|---:|---|---:|---:|")
    seen = set()
    for r in rows:
        if r["mesh"] in seen:
            continue
        seen.add(r["mesh"])
        so = r["solid"]
        L.append(f"| {r['mesh']} | {so['mesh_facets']} | {so['faces']} | {so['edges']} | "
                 f"{'yes' if so['valid'] else 'no'} | {secs(so['seconds_solid'])} | "
                 f"{secs(so['seconds_remove_splitter'])} |")
    text = "\n".join(L) + "\n"
    with open(out_path, "w") as f:
        f.write(text)
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build-dir", default=os.path.join(REPO, "build"))
    ap.add_argument("--meshes", nargs="+", default=DEFAULT_MESHES,
                    help="names in data/meshes (without .off) or paths")
    ap.add_argument("--views", nargs="+", default=DEFAULT_VIEWS)
    ap.add_argument("--repeats", type=int, default=5, help="timing: best of this many runs")
    ap.add_argument("--work-dir", default=None, help="raw JSON (default BUILD/hlr_peers)")
    ap.add_argument("--out", default=os.path.join(HERE, "hlr_peers.md"))
    ap.add_argument("--svg", action="store_true", help="also write both drawings as SVG")
    args = ap.parse_args()

    fc, why = import_freecad()
    if fc is None:
        print(f"hlr_peers: skipped: FreeCAD's Python modules are missing ({why}). Install "
              "them with `apt-get install --no-install-recommends freecad-python3` (Debian) or "
              "set FREECAD_LIB to the directory holding FreeCAD.so.")
        return 0
    judge = os.path.join(args.build_dir, "bench", "hlr_judge")
    if not os.access(judge, os.X_OK):
        print(f"hlr_peers: skipped: {judge} is missing; build it with "
              f"`cmake --build {args.build_dir} --target hlr_judge` (EXBSP_BUILD_TESTS=ON).")
        return 0
    work = args.work_dir or os.path.join(args.build_dir, "hlr_peers")
    os.makedirs(work, exist_ok=True)

    notes = machine_notes()
    notes["freecad"] = ".".join(fc[0].Version()[:3])
    notes["load_before"] = loadavg()
    notes["date"] = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    rows = []
    for name in args.meshes:
        mesh_path = name if os.path.sep in name or name.endswith(".off") else os.path.join(
            MESHES, name + ".off")
        if not os.path.exists(mesh_path):
            log(f"{mesh_path}: missing, skipped")
            continue
        mesh = os.path.splitext(os.path.basename(mesh_path))[0]
        solid, solid_info = mesh_to_solid(fc, mesh_path)
        log(f"{mesh}: {solid_info}")
        for view in args.views:
            stem = os.path.join(work, f"{mesh}_{view}")
            head = hlr_judge(judge, mesh_path, view, "--mapping-only")
            mapping = head["mapping"]
            moved = in_camera_frame(fc, solid, mapping)
            row = {"mesh": mesh, "view": view, "solid": solid_info}
            try:
                comp, occt_s, occt_runs = occt_hlr(fc, moved, args.repeats)
                vis_edges = [e for k in VISIBLE_COMPOUNDS for e in edges_of(comp[k])]
                hid_edges = [e for k in HIDDEN_COMPOUNDS for e in edges_of(comp[k])]
                visible, c1 = to_grid_polylines(vis_edges, mapping)
                hidden, c2 = to_grid_polylines(hid_edges, mapping)
                peer = {"name": "OCCT HLRBRep_Algo (FreeCAD Drawing.projectEx)",
                        "seconds": occt_s, "visible": visible, "hidden": hidden,
                        "compound_edges": {k: len(edges_of(v)) for k, v in comp.items()},
                        "curved_edges": c1 + c2}
                with open(stem + "_occt.json", "w") as f:
                    json.dump(peer, f)
                # The same OCCT drawing with its strokes kept only on the contract's feature
                # edges (matched to the solid's 3D edges; not timed: a filter of ours).
                solid_edges = contract_edges_2d(fc, moved, CREASE_DEG)
                eps = 1e-6 * solid.BoundBox.DiagonalLength
                fvis, dv, uv = keep_on_features(vis_edges, solid_edges, eps)
                fhid, dh, uh = keep_on_features(hid_edges, solid_edges, eps)
                filtered = {"name": "OCCT HLR, strokes on the contract's feature edges only",
                            "seconds": occt_s,
                            "visible": to_grid_polylines(fvis, mapping)[0],
                            "hidden": to_grid_polylines(fhid, mapping)[0],
                            "dropped": {"visible": dv, "hidden": dh},
                            "unmatched": {"visible": uv, "hidden": uh}}
                with open(stem + "_occt_features.json", "w") as f:
                    json.dump(filtered, f)
                extra = ["--peer", stem + "_occt.json", "--peer", stem + "_occt_features.json",
                         "--repeats", str(args.repeats)]
                if args.svg:
                    extra += ["--svg-out", stem + "_exbsp.svg", "--peer-svg-out", stem + "_occt.svg",
                              "--peer-svg-out", stem + "_occt_features.svg"]
                res = hlr_judge(judge, mesh_path, view, *extra)
                row["occt_filter"] = {"dropped": filtered["dropped"],
                                      "unmatched": filtered["unmatched"],
                                      "solid_edges": len(solid_edges),
                                      "solid_feature_edges": sum(1 for e in solid_edges if e[2])}
                row.update(res)
                row["mesh"] = mesh
                row["occt_seconds"] = occt_s
                row["occt_runs"] = occt_runs
                row["occt_compounds"] = peer["compound_edges"]
                row["occt_edges"] = {"visible": len(vis_edges), "hidden": len(hid_edges)}
            except Exception as e:  # a failed HLR is a row, not the end of the run
                log(f"{mesh} {view}: {type(e).__name__}: {e}")
                res = hlr_judge(judge, mesh_path, view, "--repeats", str(args.repeats))
                row.update(res)
                row["mesh"] = mesh
                row["error"] = f"failed: {type(e).__name__}"
            with open(stem + ".json", "w") as f:
                json.dump(row, f, indent=1)
            ex, pe = row["exbsp"], row.get("peer")
            log(f"{mesh} {view}: exbsp {agreement_cell(ex)} in {secs(ex['seconds'])}; "
                + (f"OCCT {agreement_cell(pe)} in {secs(row['occt_seconds'])}; on feature edges "
                   f"{agreement_cell(row['peers'][1])}" if pe else "OCCT failed"))
            rows.append(row)
    notes["load_after"] = loadavg()
    text = write_table(rows, notes, args.out, args)
    with open(os.path.join(work, "rows.json"), "w") as f:
        json.dump({"notes": notes, "rows": rows}, f, indent=1)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
