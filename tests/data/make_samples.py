#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Writes the mesh reader samples: good meshes in tests/data/ and the malformed corpus in
tests/data/bad/ with its manifest EXPECTED.tsv (file, expected line (0 = none), message
substring). The outputs are committed; rerun after editing a case:
    python3 tests/data/make_samples.py
Deterministic: no randomness, no timestamps."""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
BAD = os.path.join(HERE, "bad")

# The test cube: an axis-aligned box whose coordinates are not exact in binary (0.1, 1.7, ...),
# so float and double readings differ. Vertex i = corner bits (x: i in 1,2,5,6; ...).
X = ("0.1", "1.7")
Y = ("-2.3", "0.6")
Z = ("0.25", "3.3")
CORNERS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_V = [(X[a], Y[b], Z[c]) for a, b, c in CORNERS]
CUBE_F = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]  # outward


def fan(face):
    return [(face[0], face[i], face[i + 1]) for i in range(1, len(face) - 1)]


CUBE_T = [t for f in CUBE_F for t in fan(f)]


def write(path, data):
    if isinstance(data, str):
        data = data.encode("ascii")
    with open(path, "wb") as f:
        f.write(data)


def off_text(vertices, faces, header="OFF"):
    lines = [header, f"{len(vertices)} {len(faces)} 0"]
    lines += [" ".join(v) for v in vertices]
    lines += [" ".join([str(len(f))] + [str(i) for i in f]) for f in faces]
    return "\n".join(lines) + "\n"


def ply_binary(endian, vtype, ctype, itype, vertices, faces, extra_vertex=True, extra_element=True):
    """A binary PLY with vertex x y z (vtype) [+ uchar red green blue], face list (ctype itype)
    + uchar flags, and an optional trailing element 'material' that must be skipped."""
    fmt = {"<": "binary_little_endian", ">": "binary_big_endian"}[endian]
    code = {"float": "f", "double": "d", "uchar": "B", "int": "i", "uint": "I", "short": "h", "char": "b", "ushort": "H"}
    head = ["ply", f"format {fmt} 1.0", "comment exbsp test sample", f"element vertex {len(vertices)}",
            f"property {vtype} x", f"property {vtype} y", f"property {vtype} z"]
    if extra_vertex:
        head += ["property uchar red", "property uchar green", "property uchar blue"]
    head += [f"element face {len(faces)}", f"property list {ctype} {itype} vertex_indices", "property uchar flags"]
    if extra_element:
        head += ["element material 2", "property float shininess", "property list uchar float tint"]
    head += ["end_header"]
    body = b""
    for v in vertices:
        body += struct.pack(endian + code[vtype] * 3, *[float(c) for c in v])
        if extra_vertex:
            body += struct.pack("BBB", 200, 40, 40)
    for f in faces:
        body += struct.pack(endian + code[ctype], len(f)) + struct.pack(endian + code[itype] * len(f), *f) + b"\x07"
    if extra_element:
        body += struct.pack(endian + "fB", 0.5, 3) + struct.pack(endian + "fff", 1, 2, 3)
        body += struct.pack(endian + "fB", 0.25, 0)
    return ("\n".join(head) + "\n").encode("ascii") + body


def stl_binary(header, triangles, count=None):
    assert len(header) <= 80
    data = header.ljust(80, b"\0") + struct.pack("<I", len(triangles) if count is None else count)
    for t in triangles:
        data += struct.pack("<3f", 0, 0, 0)
        for p in t:
            data += struct.pack("<3f", *p)
        data += b"\0\0"
    return data


def stl_ascii(triangles_text, name="cube"):
    out = [f"solid {name}"]
    for t in triangles_text:
        out += ["  facet normal 0 0 0", "    outer loop"]
        out += ["      vertex " + " ".join(p) for p in t]
        out += ["    endloop", "  endfacet"]
    out += [f"endsolid {name}"]
    return "\n".join(out) + "\n"


def good_samples():
    write(os.path.join(HERE, "cube.off"),
          off_text(CUBE_V, CUBE_F))  # no comments: OpenMesh's OFF reader cannot skip them
    # COFF: per-vertex RGBA, face colours, comments, blank lines.
    coff = ["COFF", "# per-vertex RGBA, per-face RGB", "8 6 12", ""]
    coff += [" ".join(v) + " 0.8 0.2 0.2 1" for v in CUBE_V]
    coff += ["# faces with RGB colours"]
    coff += [" ".join([str(len(f))] + [str(i) for i in f]) + " 255 0 0" for f in CUBE_F]
    write(os.path.join(HERE, "cube_coff.off"), "\n".join(coff) + "\n\n")
    # OBJ: attributes, groups, materials, a polyline; faces in all reference forms, absolute
    # and relative (negative) indices.
    obj = ["# box with relative indices and slashes", "mtllib box.mtl", "o box"]
    obj += ["v " + " ".join(v) for v in CUBE_V]
    obj += ["vt 0 0", "vt 1 0", "vt 1 1", "vt 0 1", "vn 0 0 -1", "vn 0 0 1",
            "g sides", "usemtl red", "s off", "l 1 2"]
    forms = [lambda i, k: f"{i}", lambda i, k: f"{i}/{k}", lambda i, k: f"{i}/{k}/1", lambda i, k: f"{i}//2"]
    for n, f in enumerate(CUBE_F):
        refs = []
        for k, i in enumerate(f):
            idx = (i + 1) if n % 2 == 0 else (i - 8)  # absolute 1-based, or relative to the end
            refs.append(forms[(n + k) % 4](idx, k + 1))
        obj.append("f " + " ".join(refs))
    write(os.path.join(HERE, "cube_relative.obj"), "\n".join(obj) + "\n")
    # Two PLY headers written out in full below, alike on purpose: each sample is a file a test
    # reads, and the differences (property order, types, obj_info) are the point.
    # PLY ascii, extra vertex and face properties and an extra element (OpenMesh reads it).
    ply = ["ply", "format ascii 1.0", "comment box with colours", "element vertex 8",
           "property float x", "property float y", "property float z", "property uchar red",
           "property uchar green", "property uchar blue", "element face 6",
           "property list uchar int vertex_indices", "property uchar flags",
           "element edge 1", "property int vertex1", "property int vertex2", "end_header"]
    ply += [" ".join(v) + " 255 0 0" for v in CUBE_V]
    ply += [" ".join([str(len(f))] + [str(i) for i in f]) + " 7" for f in CUBE_F]
    ply += ["0 1"]
    write(os.path.join(HERE, "cube_ascii.ply"), "\n".join(ply) + "\n")
    # PLY ascii that OpenMesh 9 cannot read (it drops the faces): a face property before the
    # index list, a lone nx with nan values, a float list, obj_info, blank lines, CRLF.
    ply = ["ply", "format ascii 1.0", "obj_info made by make_samples.py", "element vertex 8",
           "property double x", "property float y", "property float z", "property float nx",
           "property uchar red", "element face 6", "property uchar flags",
           "property list uchar uint vertex_index", "property list uchar float texcoord",
           "element edge 1", "property int vertex1", "property int vertex2", "end_header"]
    ply += [" ".join(v) + " nan 255" for v in CUBE_V]
    ply += [""]
    ply += ["7 " + " ".join([str(len(f))] + [str(i) for i in f]) + " 2 0.5 0.5" for f in CUBE_F]
    ply += ["0 1", ""]
    write(os.path.join(HERE, "cube_ascii_extras.ply"), "\r\n".join(ply) + "\r\n")
    write(os.path.join(HERE, "cube_binary_le.ply"), ply_binary("<", "double", "uchar", "int", CUBE_V, CUBE_F))
    write(os.path.join(HERE, "cube_binary_be.ply"), ply_binary(">", "float", "uchar", "uint", CUBE_V, CUBE_F))
    tri_text = [[CUBE_V[i] for i in t] for t in CUBE_T]
    write(os.path.join(HERE, "cube_ascii.stl"), stl_ascii(tri_text))
    tri_float = [[tuple(float(c) for c in CUBE_V[i]) for i in t] for t in CUBE_T]
    write(os.path.join(HERE, "cube_binary.stl"),
          stl_binary(b"solid cube: a binary STL whose header starts with 'solid'", tri_float))
    # Fan order and face ids: a pentagon, a triangle and a hexagon.
    fan_v = [("0", "0", "0"), ("2", "0", "0"), ("3", "1", "0"), ("1", "2", "0"), ("-1", "1", "0"),
             ("0", "0", "1"), ("1", "0", "1"), ("0", "1", "1"),
             ("0", "0", "2"), ("1", "0", "2"), ("2", "1", "2"), ("1", "2", "2"), ("0", "2", "2"), ("-1", "1", "2")]
    write(os.path.join(HERE, "fan.off"),
          off_text(fan_v, [(0, 1, 2, 3, 4), (5, 6, 7), (8, 9, 10, 11, 12, 13)]))
    # Non-manifold input that must load completely: three triangles on one edge (0,1), a
    # duplicated face, the same face in both orientations, a degenerate (collinear) face.
    nm_v = [("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0"), ("0", "-1", "0"), ("0", "0", "1"),
            ("2", "0", "0")]
    nm_f = [(0, 1, 2), (0, 1, 3), (1, 0, 4), (0, 1, 2), (2, 1, 0), (0, 1, 5)]
    write(os.path.join(HERE, "nonmanifold.off"), off_text(nm_v, nm_f))
    nm_obj = ["v " + " ".join(v) for v in nm_v] + ["f " + " ".join(str(i + 1) for i in f) for f in nm_f]
    write(os.path.join(HERE, "nonmanifold.obj"), "\n".join(nm_obj) + "\n")
    # Decimal forms and correctly rounded values (see test_mesh.cpp, ExactDecimal*).
    dec = ["OFF", "6 1 0",
           "0.1 0.1000000000000000055511151231257827 0.30000000000000004",
           "1e-3 -0 .5",
           "5. +2 1E2",
           "9007199254740993 2.2250738585072011e-308 1e-400",
           "4.9e-324 -1e-400 1.7976931348623157e308",
           "0.1e1 123456789012345678901234567890 0.000001",
           "3 0 1 2"]
    write(os.path.join(HERE, "exact_decimal.off"), "\n".join(dec) + "\n")


def bad_corpus():
    os.makedirs(BAD, exist_ok=True)
    for name in os.listdir(BAD):
        os.remove(os.path.join(BAD, name))
    cases = []  # (file, line, substring)

    def case(name, data, line, substring):
        write(os.path.join(BAD, name), data)
        cases.append((name, line, substring))

    garbage = bytes((i * 167 + 13) % 256 for i in range(300))  # fixed pseudo-random bytes
    elf = b"\x7fELF\x02\x01\x01\x00" + bytes(range(0, 256, 3))
    tri = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n"

    # ---- OFF ----
    case("off_empty.off", b"", 0, "empty file")
    case("off_garbage.off", garbage, 1, "expected an OFF header")
    case("off_elf.off", elf, 1, "expected an OFF header")
    case("off_only_comments.off", "# nothing here\n\n# really\n", 3, "no OFF header")
    case("off_missing_counts.off", "OFF\n# counts follow?\n", 2, "missing the counts line")
    case("off_truncated_vertices.off", "OFF\n8 6 12\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0", 7, "vertex 4 has 2 coordinates")
    case("off_missing_vertices.off", "OFF\n8 6 12\n0 0 0\n1 0 0\n0 1 0\n", 5, "unexpected end of file: read 3 of 8 vertices")
    case("off_missing_faces.off", tri.replace("3 1 0", "3 4 0") + "3 0 1 2\n3 2 1 0\n", 7, "read 2 of 4 faces")
    case("off_huge_vertex_count.off", "OFF\n4000000000 1 0\n0 0 0\n1 0 0\n0 1 0\n", 5,
         "read 3 of 4000000000 vertices")
    case("off_huge_face_count.off", tri.replace("3 1 0", "3 4000000000 0") + "3 0 1 2\n", 6,
         "read 1 of 4000000000 faces")
    case("off_count_too_large.off", "OFF\n5000000000 1 0\n0 0 0\n", 2, "exceeds the supported maximum")
    case("off_negative_count.off", "OFF\n-3 1 0\n", 2, "vertex count -3 is negative")
    case("off_extra_face.off", tri + "3 0 1 2\n3 0 2 1\n", 7, "unexpected data after the last face")
    case("off_extra_vertex_columns.off", "OFF\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n", 3,
         "extra columns need a COFF")
    case("off_nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", 4, "x coordinate 'nan' is not finite")
    case("off_inf.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 -inf 0\n3 0 1 2\n", 5, "y coordinate '-inf' is not finite")
    case("off_overflow.off", "OFF\n3 1 0\n0 0 1e999\n1 0 0\n0 1 0\n3 0 1 2\n", 3, "overflows double")
    case("off_not_a_number.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 zero\n3 0 1 2\n", 5, "z coordinate 'zero' is not a number")
    case("off_hex_number.off", "OFF\n3 1 0\n0x1p3 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 3, "is not a number")
    case("off_index_out_of_range.off", "OFF\n9 1 0\n" + "0 0 0\n" * 9 + "\n# the face\n3 0 12 1\n", 14,
         "vertex index 12 out of range (9 vertices)")
    case("off_negative_index.off", tri + "3 0 -1 2\n", 6, "vertex index -1 out of range (3 vertices)")
    case("off_face_two_vertices.off", tri + "2 0 1\n", 6, "has 2 vertices (at least 3 needed)")
    case("off_face_missing_indices.off", tri + "4 0 1 2\n", 6, "declares 4 vertices but lists only 3 indices")
    case("off_face_too_many_values.off", tri + "3 0 1 2 1 1 1 1 1\n", 6, "at most 4 colour values")
    case("off_face_count_not_integer.off", tri + "3.0 0 1 2\n", 6, "face vertex count '3.0' is not an integer")
    case("off_binary.off", "OFF BINARY\n" + "\0" * 40, 1, "binary OFF is not supported")
    case("off_4d.off", "4OFF\n3 1 0\n0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n", 1, "not supported")

    # ---- OBJ ----
    obj_tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
    case("obj_empty.obj", b"", 0, "empty file")
    case("obj_garbage.obj", elf, 1, "unsupported OBJ statement")
    case("obj_only_comments.obj", "# just a comment\n\n", 2, "no OBJ statements")
    case("obj_truncated_vertex.obj", obj_tri + "v 1 1", 4, "vertex has 2 coordinates")
    case("obj_truncated_face.obj", obj_tri + "v 1 1 0\nf 1 2 3\nf 1 2", 6, "face 1 has 2 vertices (at least 3 needed)")
    case("obj_nan.obj", "v 0 0 0\nv NaN 0 0\nv 0 1 0\nf 1 2 3\n", 2, "x coordinate 'NaN' is not finite")
    case("obj_inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 Infinity\nf 1 2 3\n", 3, "z coordinate 'Infinity' is not finite")
    case("obj_overflow.obj", "v 0 -1e400 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 1, "overflows double")
    case("obj_index_out_of_range.obj", obj_tri + "f 1 2 5\n", 4, "vertex index 5 out of range (3 vertices defined so far)")
    case("obj_relative_out_of_range.obj", obj_tri + "f -1 -2 -4\n", 4, "vertex index -4 out of range")
    case("obj_forward_reference.obj", "f 1 2 3\n" + obj_tri, 1, "out of range (0 vertices defined so far)")
    case("obj_zero_index.obj", obj_tri + "f 0 1 2\n", 4, "vertex index 0 is invalid")
    case("obj_bad_reference.obj", obj_tri + "f 1/1/1/1 2 3\n", 4, "invalid face vertex reference")
    case("obj_bad_slashes.obj", obj_tri + "f 1// 2 3\n", 4, "invalid face vertex reference")
    case("obj_face_two_vertices.obj", obj_tri + "f 1 2\n", 4, "at least 3 needed")
    case("obj_freeform.obj", obj_tri + "cstype bspline\ndeg 3\nsurf 0 1 0 1 1 2 3\n", 4, "unsupported OBJ statement 'cstype'")
    case("obj_continued_bad_face.obj", obj_tri + "f 1 2 \\\n 7\n", 4, "vertex index 7 out of range")

    # ---- PLY ----
    ply_head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n" \
               "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    ply_verts = "0 0 0\n1 0 0\n0 1 0\n"
    case("ply_empty.ply", b"", 0, "empty file")
    case("ply_garbage.ply", garbage, 1, "not a PLY file")
    case("ply_no_end_header.ply", ply_head.replace("end_header\n", "comment the header never ends\n"), 9,
         "no 'end_header'")
    case("ply_truncated_ascii.ply", ply_head + "0 0 0\n1 0 0\n", 11, "read 2 of 3 instances of element 'vertex'")
    case("ply_missing_faces.ply", ply_head + ply_verts, 12, "read 0 of 1 instances of element 'face'")
    case("ply_huge_count_ascii.ply", ply_head.replace("vertex 3", "vertex 4000000000") + ply_verts, 12,
         "read 3 of 4000000000 instances")
    case("ply_nan.ply", ply_head + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", 11, "y coordinate 'nan' is not finite")
    case("ply_inf.ply", ply_head + "0 0 0\n1 0 0\n0 1 -inf\n3 0 1 2\n", 12, "z coordinate '-inf' is not finite")
    case("ply_index_out_of_range.ply", ply_head + ply_verts + "3 0 1 3\n", 13, "vertex index 3 out of range (3 vertices)")
    case("ply_face_two_vertices.ply", ply_head + ply_verts + "2 0 1\n", 13, "has 2 vertices (at least 3 needed)")
    case("ply_too_many_values.ply", ply_head + "0 0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 10, "too many values")
    case("ply_too_few_values.ply", ply_head + ply_verts + "3 0 1\n", 13, "too few values")
    case("ply_extra_data.ply", ply_head + ply_verts + "3 0 1 2\n0 0 0\n", 14, "unexpected data after the last element")
    case("ply_count_does_not_fit.ply", ply_head + ply_verts + "300 0 1 2\n", 13, "does not fit its type uchar")
    case("ply_missing_z.ply", ply_head.replace("property float z\n", ""), 3, "has no 'z' property")
    case("ply_no_face_list.ply", ply_head.replace("property list uchar int vertex_indices", "property int vertex_indices"),
         8, "must be a list")
    case("ply_unknown_type.ply", ply_head.replace("property float y", "property int64 y"), 5, "unknown property type 'int64'")
    case("ply_bad_format.ply", ply_head.replace("ascii", "binary_middle_endian"), 2, "unknown PLY format")
    case("ply_float_indices.ply", ply_head.replace("uchar int vertex", "uchar float vertex"), 8, "integer type")
    le = ply_binary("<", "float", "uchar", "int", CUBE_V, CUBE_F, extra_vertex=False, extra_element=False)
    case("ply_binary_truncated.ply", le[:-20], 0, "unexpected end of file in element 'face' #4")
    be = ply_binary(">", "float", "uchar", "int", [("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0")], [(0, 1, 2)],
                    extra_vertex=False, extra_element=False)
    be_nan = be.replace(struct.pack(">f", 1.0), struct.pack(">f", float("nan")), 1)
    case("ply_binary_be_nan.ply", be_nan, 0, "x coordinate is not finite")
    le_small = ply_binary("<", "float", "uchar", "int", [("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0")], [(0, 1, 9)],
                          extra_vertex=False, extra_element=False)
    case("ply_binary_index_out_of_range.ply", le_small, 0, "vertex index 9 out of range (3 vertices)")
    huge = ply_binary("<", "float", "uchar", "int", [("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0")], [(0, 1, 2)],
                      extra_vertex=False, extra_element=False).replace(b"element vertex 3", b"element vertex 4000000000")
    case("ply_binary_huge_count.ply", huge, 0, "declares 4000000000 instances")
    le_good = ply_binary("<", "float", "uchar", "int", [("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0")], [(0, 1, 2)],
                         extra_vertex=False, extra_element=False)
    case("ply_binary_trailing_garbage.ply", le_good + b"GARBAGE", 0,
         "unexpected data after the last element")
    two = ply_binary("<", "float", "char", "int", [("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0")], [(0, 1)],
                     extra_vertex=False, extra_element=False)
    case("ply_binary_face_two_vertices.ply", two, 0, "has 2 vertices (at least 3 needed)")

    # ---- STL ----
    tri3 = [[("0", "0", "0"), ("1", "0", "0"), ("0", "1", "0")]]
    good_ascii = stl_ascii(tri3, "t")  # 9 lines
    case("stl_empty.stl", b"", 0, "empty file")
    case("stl_garbage.stl", garbage, 0, "binary STL declares")
    case("stl_too_short.stl", "hello world\n", 0, "not an STL file")
    tri_f = [[(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)]] * 10
    case("stl_binary_truncated.stl", stl_binary(b"binary", tri_f, count=12), 0, "declares 12 triangles (684 bytes)")
    case("stl_binary_huge_count.stl", stl_binary(b"binary", tri_f[:2], count=0xFFFFFFFF), 0,
         "declares 4294967295 triangles")
    case("stl_binary_solid_header_bad_count.stl", stl_binary(b"solid but binary", tri_f, count=11), 0,
         "declares 11 triangles")
    case("stl_binary_nan.stl", stl_binary(b"binary", [[(0.0, 0.0, 0.0), (float("nan"), 0.0, 0.0), (0.0, 1.0, 0.0)]]),
         0, "triangle #0 (byte offset 84): coordinate is not finite")
    case("stl_binary_inf.stl", stl_binary(b"binary", tri_f[:3] + [[(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, float("-inf"), 0.0)]]),
         0, "triangle #3")
    case("stl_ascii_truncated.stl", "\n".join(good_ascii.split("\n")[:5]) + "\n", 5, "unexpected end of file")
    case("stl_ascii_missing_endsolid.stl", "\n".join(good_ascii.split("\n")[:8]) + "\n", 8, "'facet' or 'endsolid'")
    case("stl_ascii_nan.stl", good_ascii.replace("vertex 1 0 0", "vertex nan 0 0"), 5, "x coordinate 'nan' is not finite")
    case("stl_ascii_inf.stl", good_ascii.replace("vertex 0 1 0", "vertex 0 1 inf"), 6, "z coordinate 'inf' is not finite")
    case("stl_ascii_two_vertices.stl", good_ascii.replace("      vertex 0 1 0\n", ""), 6, "has 2 vertices (at least 3 needed)")
    case("stl_ascii_bad_keyword.stl", good_ascii.replace("vertex 1 0 0", "vertx 1 0 0"), 5, "expected 'vertex' or 'endloop'")
    case("stl_ascii_bad_number.stl", good_ascii.replace("vertex 1 0 0", "vertex 1 0 0,5"), 5, "is not a number")
    case("stl_ascii_trailing_garbage.stl", good_ascii + "garbage\n", 10, "expected 'solid' or the end of file")
    case("stl_ascii_missing_loop.stl", good_ascii.replace("outer loop", "outer"), 4, "expected 'loop'")

    # ---- any format ----
    case("unknown_extension.xyz", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 0, "supported mesh formats: .off, .obj, .ply, .stl")

    with open(os.path.join(BAD, "EXPECTED.tsv"), "w") as f:
        for name, line, substring in cases:
            assert "\t" not in substring
            f.write(f"{name}\t{line}\t{substring}\n")


if __name__ == "__main__":
    good_samples()
    bad_corpus()
