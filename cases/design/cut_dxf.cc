// write_cut_dxf (cases/design/stocking_cut.h), with dxflib's writer: a DXF R12 file in the AAMA
// convention the pattern reader reads (pattern/dxf_reader.h).
#include "cases/design/stocking_cut.h"

#include <dl_dxf.h>

#include <memory>
#include <stdexcept>

namespace tightfit {

void write_cut_dxf(const std::string& path, const std::string& piece,
                   const std::vector<CutKnot>& knots) {
  const CutOutline outline = cut_outline(knots);
  DL_Dxf dxf;
  std::unique_ptr<DL_WriterA> w(dxf.out(path.c_str(), DL_Codes::AC1009));
  if (!w) throw std::runtime_error("cannot write '" + path + "'");
  // Header: the units, mm ($INSUNITS 4).
  w->sectionHeader();
  w->dxfString(9, "$INSUNITS");
  w->dxfInt(70, 4);
  w->sectionEnd();

  w->sectionBlocks();
  dxf.writeBlock(*w, DL_BlockData(piece, 0, 0.0, 0.0, 0.0));
  const int n = static_cast<int>(outline.points_mm.size());
  dxf.writePolyline(*w, DL_PolylineData(n, 0, 0, 1 /* closed */),
                    DL_Attributes("1", 256, -1, "BYLAYER", 1.0));
  for (const Vec2& p : outline.points_mm)
    dxf.writeVertex(*w, DL_VertexData(p.x(), p.y(), 0.0, 0.0));
  dxf.writePolylineEnd(*w);
  for (int c : outline.corners)
    dxf.writePoint(*w, DL_PointData(outline.points_mm[c].x(), outline.points_mm[c].y(), 0.0),
                   DL_Attributes("2", 256, -1, "BYLAYER", 1.0));
  // The grain line: the warp, along the limb.
  const double mid = 0.5 * outline.width_mm;
  dxf.writeLine(*w,
                DL_LineData(mid, 0.1 * outline.height_mm, 0.0, mid, 0.9 * outline.height_mm, 0.0),
                DL_Attributes("7", 256, -1, "BYLAYER", 1.0));
  dxf.writeText(*w,
                DL_TextData(mid, 0.5 * outline.height_mm, 0.0, 0.0, 0.0, 0.0, 10.0, 1.0, 0, 0, 0,
                            "PIECE NAME: " + piece, "STANDARD", 0.0),
                DL_Attributes("1", 256, -1, "BYLAYER", 1.0));
  dxf.writeEndBlock(*w, piece);
  w->sectionEnd();
  w->dxfEOF();
  w->close();
}

}  // namespace tightfit
