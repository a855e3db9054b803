// A small, dependency-free SVG figure writer for reports (`hecal contour study --plot` and
// --covariance-plot, docs/contour.md#the-experiments): a grid of 2-D plot panels, each with line
// plots (solid or dashed, e.g. mean error and ±2σ bands versus a motion value), scatter points
// (dots, circles, crosses) and k-sigma covariance ellipses, drawn like a paper figure. Units are
// the data's; the figure maps them to SVG user units (px). No errors: every input draws.
//
//   svg::Panel panel{.title = "rotation", .x_label = "motion (deg)", .y_label = "error (deg)"};
//   panel.lines.push_back({.label = "mean", .x = motion, .y = mean});
//   panel.lines.push_back({.label = "±2σ", .x = motion, .y = upper, .dashed = true});
//   const std::string document = svg::Figure({panel}, {.title = "Figure 3"});
//
// Output: one standalone SVG document (UTF-8), deterministic for given input: pixel coordinates
// are written with at most 2 decimals, tick labels with the decimals their tick step needs.
// Axes: each panel's ranges cover every finite line vertex, point and ellipse (its axis-aligned
// bounding box) plus a 5% margin on each side; a degenerate range (one value) is widened to
// ±10% of the value (±1 around 0); a panel without data shows [0, 1]. Ticks are the multiples
// of a "nice" step (1, 2 or 5 × 10^k) inside the range. The y axis points up.
// Lines: a non-finite x or y ends the current polyline; the next finite vertex starts a new one
// (an isolated finite vertex is drawn as a dot). Points and ellipses with non-finite values are
// skipped. Ellipses are polygons through scale·sqrt(eigenvalue) semi-axes along the
// eigenvectors of the 2×2 covariance (its symmetric part; negative eigenvalues count as 0).
// Drawing order: points, ellipses, lines (on top). Legend: per panel, the non-empty labels in
// order lines, points, ellipses, first occurrence of each label only, in the corner of the plot
// area that hides the least data. All text is XML-escaped; control characters are dropped.
// Elements carry classes (line, points, ellipse, legend, tick-label, ...) so tests and style
// sheets can find them.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace hecal::report::svg {

// A polyline through (x[i], y[i]); the longer of x and y is cut to the shorter.
struct Line {
  std::string label{};
  std::vector<double> x{}, y{};
  std::string color = "#1f77b4";
  bool dashed = false;
  double width = 1.5;  // stroke width, pixels
};

struct Points {
  enum class Marker { kDot, kCross, kCircle };
  std::string label{};
  std::vector<Eigen::Vector2d> xy{};
  std::string color = "#ff7f0e";
  Marker marker = Marker::kDot;
  double size = 1.5;  // marker radius (half the cross width), pixels
  double opacity = 1.0;
};

// The curve (p - centre)ᵀ covariance⁻¹ (p - centre) = scale².
struct Ellipse {
  std::string label{};
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Identity();
  double scale = 2.0;  // k-sigma
  std::string color = "#d62728";
  bool dashed = false;
  double width = 1.2;
};

struct Panel {
  std::string title{}, x_label{}, y_label{};
  std::vector<Line> lines{};
  std::vector<Points> points{};
  std::vector<Ellipse> ellipses{};
  bool legend = true;
};

struct FigureOptions {
  std::string title{};     // above all panels; none when empty
  int columns = 3;         // panels per row (at least 1)
  int panel_width = 360;   // px, at least kMinPanelWidth
  int panel_height = 260;  // px, at least kMinPanelHeight

  // The smallest panel that holds the axes, tick labels and a legend.
  static constexpr int kMinPanelWidth = 120;
  static constexpr int kMinPanelHeight = 100;
  // core/options_check.h: false naming FigureOptions.columns (below 1), .panel_width or
  // .panel_height (below the smallest panel).
  bool IsValid(std::string* why) const;
};

// The complete SVG document for `panels`, laid out row by row in options.columns columns. Throws
// hecal::InputError when !options.IsValid (so does LayoutPanel).
std::string Figure(const std::vector<Panel>& panels, const FigureOptions& options);

// ---- The pieces Figure is built from, public for tests and callers that need the mapping ----

struct Range {
  double lo = 0.0, hi = 1.0;
};

// Tick positions on an axis: multiples of `step`, ascending.
struct Ticks {
  double step = 1.0;
  std::vector<double> values{};
};

// Where panel `index` of a figure draws its data: the plot area in figure pixels and the data
// ranges mapped onto it (x.lo → left edge, x.hi → right edge, y.lo → bottom, y.hi → top).
struct PanelLayout {
  double left = 0.0, top = 0.0, width = 1.0, height = 1.0;
  Range x, y;
  Ticks x_ticks{}, y_ticks{};

  double MapX(double value) const { return left + (value - x.lo) / (x.hi - x.lo) * width; }
  double MapY(double value) const { return top + (y.hi - value) / (y.hi - y.lo) * height; }
  double UnmapX(double pixel) const { return x.lo + (pixel - left) / width * (x.hi - x.lo); }
  double UnmapY(double pixel) const { return y.hi - (pixel - top) / height * (y.hi - y.lo); }
};

PanelLayout LayoutPanel(const Panel& panel, std::size_t index, const FigureOptions& options);

// The data range of a panel before ticks: finite extent plus 5% margin (see the file comment).
Range DataRange(const std::vector<double>& values);

// 1, 2 or 5 × 10^k nearest (on a log scale) to span / target, so that span / step is within
// [0.63, 1.59] × target.
double NiceStep(double span, int target);
// The multiples of NiceStep(hi - lo, target) in [lo, hi] (with a tiny tolerance); when that
// gives fewer than 2 ticks, the next smaller nice steps until it gives 2. No ticks when the range
// is empty or not finite.
Ticks NiceTicks(double lo, double hi, int target = 5);
// A tick value written with as many decimals as `step` needs ("0.25", "-3"), in compact
// scientific notation ("1.5e6", "2e-5") from |value| ≥ 1e6 or step < 1e-4; never "-0".
std::string FormatTick(double value, double step);

// The semi-axes (scale·sqrt(eigenvalue), major ≥ minor) of a covariance ellipse and the angle of
// its major axis from +x in radians, in (-π/2, π/2], counter-clockwise in data coordinates.
struct EllipseAxes {
  double major = 0.0, minor = 0.0, angle = 0.0;
};
EllipseAxes AxesOf(const Eigen::Matrix2d& covariance, double scale);

// `text` with & < > " ' replaced by entities and control characters (other than tab and
// newline) removed, so it can go into SVG text or attribute values.
std::string EscapeXml(std::string_view text);

}  // namespace hecal::report::svg
