// SPDX-License-Identifier: GPL-3.0-or-later
// DXF writer of a drawing sheet over dxflib (notation in sheet_dxf.h). dxflib writes only to a
// named file, so the document goes to a private temporary file (mkstemp) that is read back and
// removed; the caller writes the bytes where they belong, atomically.
#include "drawing/sheet_dxf.h"

#include <dxflib/dl_dxf.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>

#include <exbsp/core/errors.h>
#include "core/atomic_file.h"

namespace exbsp::drawing {

namespace {

struct layer_style {
  layer_id layer;
  const char* linetype;
  line_style style;
};

constexpr layer_style dxf_layers[] = {
    {layer_id::hatching, "CONTINUOUS", line_style::continuous},
    {layer_id::hidden, "HIDDEN", line_style::dashed},
    {layer_id::visible, "CONTINUOUS", line_style::continuous},
    {layer_id::cutting_planes, "DASHDOT", line_style::chain},
    {layer_id::frame, "CONTINUOUS", line_style::continuous},
};

/// DXF line weights are hundredths of a millimetre from a fixed list (the nearest one).
int line_weight(double mm) {
  static const int weights[] = {0,  5,  9,  13, 15, 18,  20,  25,  30,  35,  40,  50,
                                53, 60, 70, 80, 90, 100, 106, 120, 140, 158, 200, 211};
  int best = 25;
  double gap = INFINITY;
  for (int w : weights)
    if (std::fabs(w - mm * 100) < gap) {
      gap = std::fabs(w - mm * 100);
      best = w;
    }
  return best;
}

/// The most common width of the sheet's polylines on `layer` (the layer's line weight).
double layer_width(const sheet& s, layer_id layer, double fallback) {
  std::vector<std::pair<double, std::size_t>> counts;
  for (const sheet_polyline& l : s.lines) {
    if (l.layer != layer) continue;
    bool found = false;
    for (auto& c : counts)
      if (c.first == l.width) {
        ++c.second;
        found = true;
      }
    if (!found) counts.emplace_back(l.width, 1);
  }
  double best = fallback;
  std::size_t n = 0;
  for (const auto& c : counts)
    if (c.second > n) {
      n = c.second;
      best = c.first;
    }
  return best;
}

/// dxflib writes only to a file name: a private temporary file (mkstemp in TMPDIR), removed
/// afterwards and on a signal (core/atomic_file.h).
class temporary_file {
 public:
  temporary_file()
      : file_(removed_on_signal::create(std::string(std::getenv("TMPDIR") && *std::getenv("TMPDIR")
                                                        ? std::getenv("TMPDIR")
                                                        : "/tmp") +
                                        "/exbsp-dxf-XXXXXX")) {}
  const std::string& path() const { return file_->path(); }

 private:
  std::unique_ptr<removed_on_signal> file_;
};

/// DXF text: ASCII as it is, every other UTF-8 character as DXF's \U+XXXX escape (the file's
/// code page is ANSI_1252, so raw UTF-8 bytes would be read as three Latin-1 characters).
std::string dxf_text(const std::string& utf8) {
  std::string out;
  for (std::size_t i = 0; i < utf8.size();) {
    const unsigned char c = static_cast<unsigned char>(utf8[i]);
    if (c < 0x80) {
      out += static_cast<char>(c);
      ++i;
      continue;
    }
    const int extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
    unsigned long cp = extra == 3 ? c & 0x07u : extra == 2 ? c & 0x0Fu : c & 0x1Fu;
    bool ok = extra > 0 && i + static_cast<std::size_t>(extra) < utf8.size();
    for (int k = 1; ok && k <= extra; ++k) {
      const unsigned char d = static_cast<unsigned char>(utf8[i + static_cast<std::size_t>(k)]);
      ok = (d & 0xC0u) == 0x80u;
      cp = (cp << 6) | (d & 0x3Fu);
    }
    if (!ok) {  // not UTF-8: one replacement character for the byte
      out += "?";
      ++i;
      continue;
    }
    char buf[16];
    std::snprintf(buf, sizeof buf, "\\U+%04lX", cp);
    out += buf;
    i += static_cast<std::size_t>(extra) + 1;
  }
  return out;
}

}  // namespace

std::string sheet_dxf(const sheet& s) {
  temporary_file tmp;
  {
    DL_Dxf dxf;
    std::unique_ptr<DL_WriterA> dw(dxf.out(tmp.path().c_str(), DL_Codes::AC1015));
    if (!dw) throw output_error(tmp.path(), "dxflib cannot open its output file");
    dxf.writeHeader(*dw);
    dw->dxfString(9, "$INSUNITS");
    dw->dxfInt(70, 4);  // millimetres
    dw->dxfString(9, "$MEASUREMENT");
    dw->dxfInt(70, 1);  // metric
    dw->dxfString(9, "$LWDISPLAY");
    dw->dxfInt(290, 1);
    dw->dxfString(9, "$LIMMIN");
    dw->dxfReal(10, 0);
    dw->dxfReal(20, 0);
    dw->dxfString(9, "$LIMMAX");
    dw->dxfReal(10, s.width);
    dw->dxfReal(20, s.height);
    dw->sectionEnd();

    dw->sectionTables();
    dxf.writeVPort(*dw);
    // Linetypes: pattern lengths in mm of paper for the widths the sheet uses.
    const double hidden_w = layer_width(s, layer_id::hidden, 0.25);
    const double chain_w = layer_width(s, layer_id::cutting_planes, 0.25);
    std::vector<double> hidden = dash_pattern(line_style::dashed, hidden_w);
    std::vector<double> chain = dash_pattern(line_style::chain, chain_w);
    for (std::size_t i = 1; i < hidden.size(); i += 2) hidden[i] = -hidden[i];  // gaps negative
    for (std::size_t i = 1; i < chain.size(); i += 2) chain[i] = -chain[i];
    const auto total = [](const std::vector<double>& p) {
      double t = 0;
      for (double v : p) t += std::fabs(v);
      return t;
    };
    dw->tableLinetypes(5);
    dxf.writeLinetype(*dw, DL_LinetypeData("BYBLOCK", "", 0, 0, 0.0));
    dxf.writeLinetype(*dw, DL_LinetypeData("BYLAYER", "", 0, 0, 0.0));
    dxf.writeLinetype(*dw, DL_LinetypeData("CONTINUOUS", "Solid line", 0, 0, 0.0));
    dxf.writeLinetype(
        *dw, DL_LinetypeData("HIDDEN", "ISO 128 dashed __ __ __", 0,
                             static_cast<int>(hidden.size()), total(hidden), hidden.data()));
    dxf.writeLinetype(*dw,
                      DL_LinetypeData("DASHDOT", "ISO 128 long-dash dotted ____ . ____", 0,
                                      static_cast<int>(chain.size()), total(chain), chain.data()));
    dw->tableEnd();
    dw->tableLayers(1 + static_cast<int>(std::size(dxf_layers)));
    dxf.writeLayer(*dw, DL_LayerData("0", 0), DL_Attributes("", 7, 25, "CONTINUOUS", 1.0));
    for (const layer_style& l : dxf_layers) {
      const double fallback =
          l.layer == layer_id::visible || l.layer == layer_id::frame ? 0.5 : 0.25;
      dxf.writeLayer(
          *dw, DL_LayerData(layer_name(l.layer), 0),
          DL_Attributes("", 7, line_weight(layer_width(s, l.layer, fallback)), l.linetype, 1.0));
    }
    dw->tableEnd();
    dw->tableStyle(1);
    dxf.writeStyle(*dw, DL_StyleData("Standard", 0, 0.0, 1.0, 0.0, 0, 2.5, "txt", ""));
    dw->tableEnd();
    dxf.writeView(*dw);
    dxf.writeUcs(*dw);
    dw->tableAppid(1);
    dxf.writeAppid(*dw, "ACAD");
    dw->tableEnd();
    dxf.writeDimStyle(*dw, 2.5, 0.625, 0.625, 0.625, 2.5);
    // The block records of model space and paper space, with the handles dxflib's BLOCKs
    // expect (1F, 1B). Written here, not by dxflib's writeBlockRecord(), because that also
    // writes a second paper space and points the records at the LAYOUT objects of
    // writeObjects(), whose dictionaries lack their owner handles: ezdxf's audit then reports
    // fixes. Without the OBJECTS section a reader makes its default layouts.
    dw->dxfString(0, "TABLE");
    dw->dxfString(2, "BLOCK_RECORD");
    dw->dxfHex(5, 1);
    dw->dxfString(100, "AcDbSymbolTable");
    dw->dxfInt(70, 2);
    for (const auto& [handle, name] : {std::pair<int, const char*>{0x1F, "*Model_Space"},
                                       std::pair<int, const char*>{0x1B, "*Paper_Space"}}) {
      dw->dxfString(0, "BLOCK_RECORD");
      dw->dxfHex(5, handle);
      dw->dxfString(100, "AcDbSymbolTableRecord");
      dw->dxfString(100, "AcDbBlockTableRecord");
      dw->dxfString(2, name);
    }
    dw->tableEnd();
    dw->sectionEnd();

    dw->sectionBlocks();
    dxf.writeBlock(*dw, DL_BlockData("*Model_Space", 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(*dw, "*Model_Space");
    dxf.writeBlock(*dw, DL_BlockData("*Paper_Space", 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(*dw, "*Paper_Space");
    dw->sectionEnd();

    dw->sectionEntities();
    for (const layer_style& ls : dxf_layers) {
      const std::string layer = layer_name(ls.layer);
      const double layer_w = layer_width(s, ls.layer, 0.25);
      for (const sheet_polyline& l : s.lines) {
        if (l.layer != ls.layer || l.points.size() < 2) continue;
        // By layer, except where a line differs from its layer (the cutting line's thick ends).
        const bool own_style = l.style != ls.style;
        const DL_Attributes attrib(layer, 256, l.width == layer_w ? -1 : line_weight(l.width),
                                   own_style ? (l.style == line_style::continuous ? "CONTINUOUS"
                                                : l.style == line_style::dashed   ? "HIDDEN"
                                                                                  : "DASHDOT")
                                             : "BYLAYER",
                                   1.0);
        if (l.points.size() == 2 && !l.closed) {
          dxf.writeLine(
              *dw, DL_LineData(l.points[0].x, l.points[0].y, 0, l.points[1].x, l.points[1].y, 0),
              attrib);
          continue;
        }
        // Flag 128: the linetype pattern runs on along the whole polyline.
        dxf.writePolyline(
            *dw, DL_PolylineData(static_cast<int>(l.points.size()), 0, 0, (l.closed ? 1 : 0) | 128),
            attrib);
        for (const point2& p : l.points) dxf.writeVertex(*dw, DL_VertexData(p.x, p.y, 0, 0));
        dxf.writePolylineEnd(*dw);
      }
      for (const sheet_fill& f : s.fills) {
        if (f.layer != ls.layer) continue;
        for (const auto& r : f.rings) {
          if (r.size() != 3) continue;  // arrowheads (fills of faces stay in SVG and PDF)
          dxf.writeSolid(*dw,
                         DL_SolidData(r[0].x, r[0].y, 0, r[1].x, r[1].y, 0, r[2].x, r[2].y, 0,
                                      r[2].x, r[2].y, 0, 0),
                         DL_Attributes(layer, 256, -1, "BYLAYER", 1.0));
        }
      }
      for (const sheet_text& t : s.texts) {
        if (t.layer != ls.layer) continue;
        // Horizontal justification 0 left, 1 centre, 2 right (then the alignment point counts).
        const int hj = t.anchor == sheet_text::anchor_kind::start    ? 0
                       : t.anchor == sheet_text::anchor_kind::middle ? 1
                                                                     : 2;
        dxf.writeText(*dw,
                      DL_TextData(t.at.x, t.at.y, 0, t.at.x, t.at.y, 0, t.height, 1.0, 0, hj, 0,
                                  dxf_text(t.text), "Standard", 0.0),
                      DL_Attributes(layer, 256, -1, "BYLAYER", 1.0));
      }
    }
    dw->sectionEnd();
    dw->dxfEOF();
    dw->close();
  }
  std::ifstream in(tmp.path(), std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in.good() && !in.eof())
    throw output_error(tmp.path(), "cannot read the DXF writer's output");
  return bytes.str();
}

}  // namespace exbsp::drawing
