#include "io/raster_canvas.h"

#include <vtkFreeTypeTools.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkStdString.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace tightfit {

RasterCanvas::RasterCanvas(int width, int height, const Vec3& background)
    : width_(width),
      height_(height),
      rgb_(static_cast<std::size_t>(width) * height, background),
      depth_(static_cast<std::size_t>(width) * height, std::numeric_limits<double>::infinity()),
      clip_x1_(width),
      clip_y1_(height) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("picture: the size must be positive");
}

void RasterCanvas::fill_triangle(const std::array<Vec3, 3>& p,
                                 const std::function<Vec3(const Vec3&)>& colour_of) {
  // Edge functions: twice the signed area of (a, b, q); their ratios to the whole are the
  // barycentric coordinates of q (either winding).
  const auto edge = [](const Vec3& a, const Vec3& b, double x, double y) {
    return (b.x() - a.x()) * (y - a.y()) - (b.y() - a.y()) * (x - a.x());
  };
  const double area = edge(p[0], p[1], p[2].x(), p[2].y());
  if (!(std::abs(area) > 0)) return;
  const int x0 =
      std::max(clip_x0_, static_cast<int>(std::floor(std::min({p[0].x(), p[1].x(), p[2].x()}))));
  const int x1 =
      std::min(clip_x1_ - 1, static_cast<int>(std::ceil(std::max({p[0].x(), p[1].x(), p[2].x()}))));
  const int y0 =
      std::max(clip_y0_, static_cast<int>(std::floor(std::min({p[0].y(), p[1].y(), p[2].y()}))));
  const int y1 =
      std::min(clip_y1_ - 1, static_cast<int>(std::ceil(std::max({p[0].y(), p[1].y(), p[2].y()}))));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double cx = x + 0.5, cy = y + 0.5;
      const Vec3 l(edge(p[1], p[2], cx, cy) / area, edge(p[2], p[0], cx, cy) / area,
                   edge(p[0], p[1], cx, cy) / area);
      if (l.minCoeff() < 0) continue;
      // Orthographic views: depth is linear in the picture's plane.
      const double depth = l[0] * p[0].z() + l[1] * p[1].z() + l[2] * p[2].z();
      const std::size_t i = static_cast<std::size_t>(y) * width_ + x;
      if (depth >= depth_[i]) continue;
      depth_[i] = depth;
      rgb_[i] = colour_of(l);
    }
}

void RasterCanvas::draw_line(const Vec3& a, const Vec3& b, double width, const Vec3& colour,
                             double depth_tolerance) {
  // Square stamps every half pixel along the segment.
  const double length = std::hypot(b.x() - a.x(), b.y() - a.y());
  const int n = std::max(1, static_cast<int>(std::ceil(2 * length)));
  const double half = 0.5 * width;
  for (int k = 0; k <= n; ++k) {
    const Vec3 p = a + (b - a) * (double(k) / n);
    const int x0 = std::max(clip_x0_, static_cast<int>(std::floor(p.x() - half + 0.5)));
    const int x1 = std::min(clip_x1_ - 1, static_cast<int>(std::floor(p.x() + half - 0.5)));
    const int y0 = std::max(clip_y0_, static_cast<int>(std::floor(p.y() - half + 0.5)));
    const int y1 = std::min(clip_y1_ - 1, static_cast<int>(std::floor(p.y() + half - 0.5)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * width_ + x;
        if (p.z() <= depth_[i] + depth_tolerance) rgb_[i] = colour;
      }
  }
}

void RasterCanvas::set_clip(int x0, int y0, int x1, int y1) {
  clip_x0_ = std::clamp(x0, 0, width_);
  clip_y0_ = std::clamp(y0, 0, height_);
  clip_x1_ = std::clamp(x1, clip_x0_, width_);
  clip_y1_ = std::clamp(y1, clip_y0_, height_);
}

void RasterCanvas::fill_rectangle(int x0, int y0, int x1, int y1, const Vec3& colour) {
  for (int y = std::max(0, y0); y < std::min(height_, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(width_, x1); ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width_ + x;
      rgb_[i] = colour;
      depth_[i] = -std::numeric_limits<double>::infinity();
    }
}

void RasterCanvas::draw_text(const std::string& text, int x, int y, int font_size, Align align) {
  vtkNew<vtkTextProperty> property;
  property->SetFontFamilyToArial();
  property->SetFontSize(font_size);
  property->SetColor(0, 0, 0);
  property->SetOpacity(1.0);
  if (align == Align::left) property->SetJustificationToLeft();
  if (align == Align::right) property->SetJustificationToRight();
  if (align == Align::centre) property->SetJustificationToCentered();
  property->SetVerticalJustificationToBottom();
  vtkNew<vtkImageData> image;
  if (!vtkFreeTypeTools::GetInstance()->RenderString(property.Get(), vtkStdString(text), 72,
                                                     image.Get()))
    return;
  // The image's extent is placed relative to the anchor (x, baseline), y upwards; its fourth
  // component is the coverage of each texel.
  int extent[6];
  image->GetExtent(extent);
  for (int j = extent[2]; j <= extent[3]; ++j)
    for (int i = extent[0]; i <= extent[1]; ++i) {
      const int px = x + i, py = y - j;
      if (px < 0 || py < 0 || px >= width_ || py >= height_) continue;
      const auto* texel = static_cast<unsigned char*>(image->GetScalarPointer(i, j, 0));
      const double alpha = texel[3] / 255.0;
      Vec3& colour = rgb_[static_cast<std::size_t>(py) * width_ + px];
      colour = (1 - alpha) * colour + alpha * Vec3(texel[0], texel[1], texel[2]) / 255.0;
    }
}

void RasterCanvas::write_png(const std::string& path) const {
  vtkNew<vtkImageData> image;
  image->SetDimensions(width_, height_, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      // VTK's images run upwards: row 0 is the bottom.
      auto* out = static_cast<unsigned char*>(image->GetScalarPointer(x, height_ - 1 - y, 0));
      const Vec3& c = rgb_[static_cast<std::size_t>(y) * width_ + x];
      for (int k = 0; k < 3; ++k)
        out[k] = static_cast<unsigned char>(std::lround(255.0 * std::clamp(c[k], 0.0, 1.0)));
    }
  // vtkPNGWriter reports a failure only through VTK's error output: check the folder first and
  // the file after.
  const std::filesystem::path file(path);
  if (file.has_parent_path() && !std::filesystem::is_directory(file.parent_path()))
    throw std::runtime_error("cannot write the picture '" + path + "': no such folder");
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
  if (writer->GetErrorCode() != 0 || !std::ifstream(path).good())
    throw std::runtime_error("cannot write the picture '" + path + "'");
}

}  // namespace tightfit
