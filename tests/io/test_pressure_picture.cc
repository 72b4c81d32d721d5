// Pressure pictures (io/pressure_picture.h, io/raster_canvas.h), read back by VTK's own PNG
// reader: the colour of a face-on surface is the colour map's at its pressure, a surface where
// no garment lies is grey, nearer triangles hide farther ones, the back view mirrors the front
// one, pressure above the colour bar's top is marked, a frame cuts the view and outlines are
// drawn where not hidden.
#include "io/pressure_picture.h"
#include "io/raster_canvas.h"
#include "scratch_dir.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <gtest/gtest.h>

namespace tightfit {
namespace {

class PressurePicture : public ScratchDir {
 protected:
  // The colour at (x, y) of a PNG file, y downwards from the top.
  static Vec3 colour_at(const std::string& file, int x, int y) {
    vtkNew<vtkPNGReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    const auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, dims[1] - 1 - y, 0));
    return Vec3(p[0], p[1], p[2]) / 255.0;
  }
  static void expect_colour(const Vec3& actual, const Vec3& expected, const char* what) {
    // 8-bit channels: half a step of rounding.
    EXPECT_LT((actual - expected).cwiseAbs().maxCoeff(), 0.5 / 255 + 1e-9)
        << what << ": " << actual.transpose() << " expected " << expected.transpose();
  }

  // The unit square in the plane z = 0 as two triangles; its left half (x < 0.5) has no
  // pressure, its right half `pressure_Pa`.
  static PressureSurface square(double pressure_Pa) {
    PressureSurface s;
    for (double y : {0.0, 1.0})
      for (double x : {0.0, 0.5, 1.0}) {
        s.points_m.emplace_back(x, y, 0.0);
        s.pressure_Pa.push_back(pressure_Pa);
        s.has_pressure.push_back(x > 0.25);
      }
    s.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
    return s;
  }
};

TEST_F(PressurePicture, FaceOnColoursAreTheColourMapsAndGreyWithoutGarment) {
  PictureStyle style;  // 800 x 600; the surface is fitted into 800 - 190 - 24 - 48 = 538 px
  style.top_pressure_Pa = 4000;
  write_pressure_picture(path("front.png"), square(2000), PictureView{}, style);
  // The drawing area is columns 24..538 and rows 40..576: the square is 514 px wide, centred
  // at (281, 308). 200 px right of the centre (x = 0.89 m): 2000 of 4000 Pa, seen face on
  // (shade 1); 200 px left (x = 0.11 m): grey.
  expect_colour(colour_at(path("front.png"), 281 + 200, 308), viridis(0.5), "right half");
  expect_colour(colour_at(path("front.png"), 281 - 200, 308), Vec3(0.78, 0.78, 0.78),
                "left half, no garment");
  // The colour bar, columns 562..586 and rows 60..566: row y shows (565 - y) / 505 of the top.
  for (int y : {62, 300, 565})
    expect_colour(colour_at(path("front.png"), 574, y), viridis((565 - y) / 505.0), "colour bar");
}

TEST_F(PressurePicture, BackViewMirrorsTheFront) {
  PictureStyle style;
  style.top_pressure_Pa = 4000;
  write_pressure_picture(path("back.png"), square(2000), PictureView{Vec3::UnitZ(), Vec3::UnitY()},
                         style);
  // Seen from behind, the pressed half (x > 0.5) is on the left.
  expect_colour(colour_at(path("back.png"), 281 - 200, 308), viridis(0.5), "pressed half");
  expect_colour(colour_at(path("back.png"), 281 + 200, 308), Vec3(0.78, 0.78, 0.78), "other half");
}

TEST(RasterCanvas, NearerTriangleHidesFartherOneWhicheverIsDrawnFirst) {
  for (bool near_first : {true, false}) {
    RasterCanvas canvas(40, 40, Vec3::Ones());
    const auto flat = [](const Vec3& colour) { return [colour](const Vec3&) { return colour; }; };
    const std::array<Vec3, 3> near{Vec3(0, 0, 1.0), Vec3(40, 0, 1.0), Vec3(0, 40, 1.0)};
    const std::array<Vec3, 3> far{Vec3(0, 0, 2.0), Vec3(40, 40, 2.0), Vec3(0, 40, 2.0)};
    if (near_first) canvas.fill_triangle(near, flat(Vec3(1, 0, 0)));
    canvas.fill_triangle(far, flat(Vec3(0, 0, 1)));
    if (!near_first) canvas.fill_triangle(near, flat(Vec3(1, 0, 0)));
    EXPECT_EQ(canvas.pixel(5, 20), Vec3(1, 0, 0));  // both cover it: the nearer one
    EXPECT_EQ(canvas.pixel(5, 38), Vec3(0, 0, 1));  // the far one alone
    EXPECT_EQ(canvas.pixel(30, 5), Vec3(1, 0, 0));  // the near one alone
    EXPECT_EQ(canvas.pixel(38, 30), Vec3::Ones());  // neither
  }
}

TEST_F(PressurePicture, PressureAboveTheTopIsMarkedInTheSurfaceAndTheBar) {
  PictureStyle style;
  style.top_pressure_Pa = 1000;  // below the 2000 Pa drawn
  write_pressure_picture(path("clipped.png"), square(2000), PictureView{}, style);
  // A legend row (26 px) now lies under the title: the drawing area is rows 66..576, the square
  // 510 px, centred at (281, 321). 200 px right of the centre: above the top, in its colour.
  expect_colour(colour_at(path("clipped.png"), 281 + 200, 321), above_top_colour(), "pressed half");
  // The swatch above the bar (rows 66..90) and the bar moved down to start at row 96.
  expect_colour(colour_at(path("clipped.png"), 574, 78), above_top_colour(), "swatch");
  expect_colour(colour_at(path("clipped.png"), 574, 96), viridis(1.0), "bar's top");
}

TEST_F(PressurePicture, FramedRoundChosenPointsWithTheOutlineOnTop) {
  PressureSurface s = square(2000);
  const auto outline = boundary_segments(s.points_m, s.triangles);
  EXPECT_EQ(outline.size(), 6u);  // the square's four sides, two of them in two halves
  s.outline_m = outline;
  // A segment 1 m behind the square (farther than the tolerance): hidden.
  s.outline_m.push_back({Vec3(0.6, 0.5, -1.0), Vec3(0.9, 0.5, -1.0)});
  s.outline_depth_tolerance_m = 0.1;
  s.frame_m = {Vec3(0.5, 0, 0), Vec3(1, 1, 0)};  // the pressed half
  PictureStyle style;
  style.top_pressure_Pa = 4000;
  write_pressure_picture(path("framed.png"), s, PictureView{}, style);
  // The frame (0.5 x 1 m) fills 90% of the 514 x 510 px area below the legend: 459 px a metre,
  // its centre (0.75, 0.5) m at (281, 321). The square's right side (x = 1 m) is at column
  // 395.75: the 2 px line covers columns 395 and 396.
  for (int x : {395, 396})
    expect_colour(colour_at(path("framed.png"), x, 321), Vec3(0.05, 0.05, 0.05), "outline");
  // Column 300 (x = 0.79 m): the pressed half, the hidden segment not drawn over it.
  expect_colour(colour_at(path("framed.png"), 300, 321), viridis(0.5), "pressed half");
  // Column 30 (x = 0.20 m): the half without garment (grey below x = 0.25 m, where the
  // corners without pressure weigh more than half), inside the area from column 24.
  expect_colour(colour_at(path("framed.png"), 30, 321), Vec3(0.78, 0.78, 0.78), "grey half");
  // Column 10, left of the area (x = 0.16 m, on the square): cut off, white.
  expect_colour(colour_at(path("framed.png"), 10, 321), Vec3(1, 1, 1), "outside the frame");
}

TEST_F(PressurePicture, UnwritableFolderIsReported) {
  EXPECT_THROW(write_pressure_picture(path("no/such/folder/p.png"), square(1), PictureView{},
                                      PictureStyle{}),
               std::runtime_error);
}

}  // namespace
}  // namespace tightfit
