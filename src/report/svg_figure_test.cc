// svg::Figure: well-formed XML, escaping, data → pixel mapping, covariance ellipses, broken
// lines, nice ticks and the legend.
#include "hecal/report/svg_figure.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cctype>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "testing/options_validity.h"

namespace hecal::report::svg {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// Pixel coordinates are written with 2 decimals.
constexpr double kPixelTolerance = 0.0051;

// ---- A tiny XML well-formedness checker: "" when `xml` is well formed, else the problem. ----

bool IsNameChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_' || c == ':' ||
         c == '.';
}

// An entity at xml[i] == '&': one of the five predefined ones or a character reference.
bool ValidEntity(const std::string& xml, std::size_t i) {
  const std::size_t end = xml.find(';', i);
  if (end == std::string::npos) return false;
  const std::string name = xml.substr(i + 1, end - i - 1);
  if (name == "amp" || name == "lt" || name == "gt" || name == "quot" || name == "apos") {
    return true;
  }
  if (name.size() >= 2 && name[0] == '#') {
    for (std::size_t k = 1; k < name.size(); ++k) {
      if (std::isxdigit(static_cast<unsigned char>(name[k])) == 0 && !(k == 1 && name[k] == 'x')) {
        return false;
      }
    }
    return true;
  }
  return false;
}

std::string CheckXml(const std::string& xml) {
  std::vector<std::string> open;
  bool root_done = false, root_seen = false;
  std::size_t i = 0;
  if (xml.rfind("<?xml", 0) == 0) {
    const std::size_t end = xml.find("?>");
    if (end == std::string::npos) return "unterminated declaration";
    i = end + 2;
  }
  while (i < xml.size()) {
    const char c = xml[i];
    if (c == '&') {
      if (!ValidEntity(xml, i)) return "bad entity at " + std::to_string(i);
      ++i;
      continue;
    }
    if (c == '>') return "raw > in text at " + std::to_string(i);
    if (c != '<') {
      if (open.empty() && std::isspace(static_cast<unsigned char>(c)) == 0) {
        return "text outside the root at " + std::to_string(i);
      }
      ++i;
      continue;
    }
    if (xml.compare(i, 4, "<!--") == 0) {
      const std::size_t end = xml.find("-->", i);
      if (end == std::string::npos) return "unterminated comment";
      i = end + 3;
      continue;
    }
    const bool closing = i + 1 < xml.size() && xml[i + 1] == '/';
    std::size_t j = i + (closing ? 2 : 1);
    const std::size_t name_start = j;
    while (j < xml.size() && IsNameChar(xml[j])) ++j;
    const std::string name = xml.substr(name_start, j - name_start);
    if (name.empty()) return "empty tag name at " + std::to_string(i);
    if (closing) {
      while (j < xml.size() && std::isspace(static_cast<unsigned char>(xml[j])) != 0) ++j;
      if (j >= xml.size() || xml[j] != '>') return "bad closing tag " + name;
      if (open.empty() || open.back() != name) return "mismatched </" + name + ">";
      open.pop_back();
      if (open.empty()) root_done = true;
      i = j + 1;
      continue;
    }
    if (root_done) return "second root element " + name;
    root_seen = true;
    std::set<std::string> attributes;
    while (true) {
      while (j < xml.size() && std::isspace(static_cast<unsigned char>(xml[j])) != 0) ++j;
      if (j >= xml.size()) return "unterminated tag " + name;
      if (xml.compare(j, 2, "/>") == 0) {
        j += 2;
        if (open.empty()) root_done = true;
        break;
      }
      if (xml[j] == '>') {
        open.push_back(name);
        ++j;
        break;
      }
      const std::size_t attribute_start = j;
      while (j < xml.size() && IsNameChar(xml[j])) ++j;
      const std::string attribute = xml.substr(attribute_start, j - attribute_start);
      if (attribute.empty()) return "bad attribute in " + name;
      if (!attributes.insert(attribute).second) return "duplicate attribute " + attribute;
      if (j + 1 >= xml.size() || xml[j] != '=' || (xml[j + 1] != '"' && xml[j + 1] != '\'')) {
        return "attribute " + attribute + " without a quoted value";
      }
      const char quote = xml[j + 1];
      const std::size_t value_end = xml.find(quote, j + 2);
      if (value_end == std::string::npos) return "unterminated value of " + attribute;
      for (std::size_t k = j + 2; k < value_end; ++k) {
        if (xml[k] == '<') return "raw < in attribute " + attribute;
        if (xml[k] == '&' && !ValidEntity(xml, k)) return "bad entity in attribute " + attribute;
      }
      j = value_end + 1;
    }
    i = j;
  }
  if (!open.empty()) return "unclosed <" + open.back() + ">";
  if (!root_seen) return "no root element";
  return "";
}

// ---- Reading the output back ----

// The opening tags (from '<' to '>') that start with `prefix`, e.g. `<polyline class="line"`.
std::vector<std::string> Tags(const std::string& svg, const std::string& prefix) {
  std::vector<std::string> tags;
  for (std::size_t at = svg.find(prefix); at != std::string::npos; at = svg.find(prefix, at + 1)) {
    tags.push_back(svg.substr(at, svg.find('>', at) - at + 1));
  }
  return tags;
}

std::string AttributeOf(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t at = tag.find(key);
  if (at == std::string::npos) return "";
  const std::size_t start = at + key.size();
  return tag.substr(start, tag.find('"', start) - start);
}

double NumberOf(const std::string& tag, const std::string& name) {
  return std::stod(AttributeOf(tag, name));
}

std::vector<Eigen::Vector2d> PointsOf(const std::string& tag) {
  std::istringstream in(AttributeOf(tag, "points"));
  std::vector<Eigen::Vector2d> points;
  double x = 0.0, y = 0.0;
  char comma = 0;
  while (in >> x >> comma >> y) points.emplace_back(x, y);
  return points;
}

// The contents of the <text class="css_class" ...> elements, still escaped.
std::vector<std::string> Texts(const std::string& svg, const std::string& css_class) {
  std::vector<std::string> texts;
  const std::string prefix = "<text class=\"" + css_class + "\"";
  for (std::size_t at = svg.find(prefix); at != std::string::npos; at = svg.find(prefix, at + 1)) {
    const std::size_t start = svg.find('>', at) + 1;
    texts.push_back(svg.substr(start, svg.find("</text>", start) - start));
  }
  return texts;
}

Panel LinePanel(std::vector<double> x, std::vector<double> y) {
  Panel panel;
  panel.title = "line";
  panel.lines.push_back({.label = "mean", .x = std::move(x), .y = std::move(y)});
  return panel;
}

Panel FullPanel() {
  Panel panel{.title = "rotation error", .x_label = "motion (deg)", .y_label = "error (deg)"};
  panel.lines.push_back({.label = "mean", .x = {1, 2, 3, 4}, .y = {0.5, 0.4, 0.3, 0.25}});
  panel.lines.push_back({.label = "mean ± 2σ",
                         .x = {1, 2, 3, 4},
                         .y = {0.9, 0.7, 0.5, 0.4},
                         .color = "#444444",
                         .dashed = true});
  panel.points.push_back({.label = "samples",
                          .xy = {{1.5, 0.6}, {2.5, 0.2}},
                          .marker = Points::Marker::kDot,
                          .opacity = 0.5});
  panel.points.push_back(
      {.label = "truth", .xy = {{2, 0.45}}, .color = "#000000", .marker = Points::Marker::kCross});
  panel.points.push_back({.label = "", .xy = {{3, 0.35}}, .marker = Points::Marker::kCircle});
  panel.ellipses.push_back({.label = "2σ",
                            .centre = {2.5, 0.5},
                            .covariance = Eigen::Vector2d(0.04, 0.01).asDiagonal(),
                            .dashed = true});
  return panel;
}

// ---- The checker itself must be able to say no ----

TEST(SvgXmlChecker, RejectsMalformedDocuments) {
  EXPECT_EQ(CheckXml("<svg a=\"1\"><g/></svg>"), "");
  EXPECT_NE(CheckXml("<svg><g></svg>"), "");
  EXPECT_NE(CheckXml("<svg><g></g>"), "");
  EXPECT_NE(CheckXml("<svg a=\"<\"/>"), "");
  EXPECT_NE(CheckXml("<svg a=\"1\" a=\"2\"/>"), "");
  EXPECT_NE(CheckXml("<svg>a & b</svg>"), "");
  EXPECT_NE(CheckXml("<svg>a > b</svg>"), "");
  EXPECT_NE(CheckXml("<svg/><svg/>"), "");
}

// ---- Figure ----

TEST(SvgFigure, IsOneWellFormedDeterministicDocument) {
  const std::vector<Panel> panels = {FullPanel(), LinePanel({0, 1}, {2, 3}), Panel{}, FullPanel()};
  const FigureOptions options{.title = "Figure 5", .columns = 3};
  const std::string svg = Figure(panels, options);
  EXPECT_EQ(CheckXml(svg), "") << svg;
  EXPECT_EQ(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>", 0), 0u);
  EXPECT_NE(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
  EXPECT_EQ(Figure(panels, options), svg);
  // 3 columns × 2 rows of 360 × 260 under a 30 px title.
  const std::string root = Tags(svg, "<svg ").at(0);
  EXPECT_EQ(AttributeOf(root, "width"), "1080");
  EXPECT_EQ(AttributeOf(root, "height"), "550");
  EXPECT_EQ(Tags(svg, "<g class=\"panel\"").size(), 4u);
  EXPECT_EQ(Tags(svg, "<polygon class=\"ellipse\"").size(), 2u);
  EXPECT_EQ(Tags(svg, "<polyline class=\"line\"").size(), 5u);
  EXPECT_EQ(Texts(svg, "figure-title"), std::vector<std::string>{"Figure 5"});
  // Dashed lines are dashed, solid ones are not.
  const std::vector<std::string> lines = Tags(svg, "<polyline class=\"line\"");
  EXPECT_EQ(AttributeOf(lines[0], "stroke-dasharray"), "");
  EXPECT_NE(AttributeOf(lines[1], "stroke-dasharray"), "");
  // Axis labels and panel titles are there.
  const std::vector<std::string> axis_labels = Texts(svg, "axis-label");
  EXPECT_EQ(std::count(axis_labels.begin(), axis_labels.end(), "motion (deg)"), 2);
  EXPECT_EQ(std::count(axis_labels.begin(), axis_labels.end(), "error (deg)"), 2);
  EXPECT_EQ(Texts(svg, "panel-title").size(), 3u);
}

TEST(SvgFigure, EscapesAllText) {
  const std::string nasty = "a<b & \"c\" 'd'>";
  const std::string escaped = "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;";
  EXPECT_EQ(EscapeXml(nasty), escaped);
  EXPECT_EQ(EscapeXml(std::string("x\x01y\tz\n", 7)), "xy\tz\n");

  Panel panel = LinePanel({0, 1}, {0, 1});
  panel.title = panel.x_label = panel.y_label = nasty;
  panel.lines[0].label = nasty;
  panel.lines[0].color = "red\" onload=\"x";
  const std::string svg = Figure({panel}, {.title = nasty});
  EXPECT_EQ(CheckXml(svg), "") << svg;
  EXPECT_EQ(svg.find("a<b"), std::string::npos);
  EXPECT_EQ(svg.find("onload=\""), std::string::npos);
  EXPECT_EQ(Texts(svg, "figure-title"), std::vector<std::string>{escaped});
  EXPECT_EQ(Texts(svg, "panel-title"), std::vector<std::string>{escaped});
  EXPECT_EQ(Texts(svg, "legend-label"), std::vector<std::string>{escaped});
  EXPECT_EQ(Texts(svg, "axis-label"), (std::vector<std::string>{escaped, escaped}));
}

TEST(SvgFigure, LineVerticesMapToThePlotArea) {
  const FigureOptions options;
  const Panel panel = LinePanel({0, 2, 10}, {-1, 3, 1});
  const PanelLayout layout = LayoutPanel(panel, 0, options);
  // Data extent plus 5% of the span on each side.
  EXPECT_DOUBLE_EQ(layout.x.lo, -0.5);
  EXPECT_DOUBLE_EQ(layout.x.hi, 10.5);
  EXPECT_DOUBLE_EQ(layout.y.lo, -1.2);
  EXPECT_DOUBLE_EQ(layout.y.hi, 3.2);
  // The range ends are the plot area's edges; y points up.
  EXPECT_DOUBLE_EQ(layout.MapX(layout.x.lo), layout.left);
  EXPECT_DOUBLE_EQ(layout.MapX(layout.x.hi), layout.left + layout.width);
  EXPECT_DOUBLE_EQ(layout.MapY(layout.y.lo), layout.top + layout.height);
  EXPECT_DOUBLE_EQ(layout.MapY(layout.y.hi), layout.top);
  EXPECT_GT(layout.left, 0.0);
  EXPECT_LT(layout.left + layout.width, options.panel_width);
  EXPECT_GT(layout.top, 0.0);
  EXPECT_LT(layout.top + layout.height, options.panel_height);

  const std::string svg = Figure({panel}, options);
  // The frame drawn is the layout's plot area.
  const std::string frame = Tags(svg, "<rect class=\"frame\"").at(0);
  EXPECT_NEAR(NumberOf(frame, "x"), layout.left, kPixelTolerance);
  EXPECT_NEAR(NumberOf(frame, "y"), layout.top, kPixelTolerance);
  EXPECT_NEAR(NumberOf(frame, "width"), layout.width, kPixelTolerance);
  EXPECT_NEAR(NumberOf(frame, "height"), layout.height, kPixelTolerance);

  const std::vector<std::string> lines = Tags(svg, "<polyline class=\"line\"");
  ASSERT_EQ(lines.size(), 1u);
  const std::vector<Eigen::Vector2d> pixels = PointsOf(lines[0]);
  ASSERT_EQ(pixels.size(), 3u);
  const double x[] = {0, 2, 10}, y[] = {-1, 3, 1};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(pixels[i].x(), layout.MapX(x[i]), kPixelTolerance) << i;
    EXPECT_NEAR(pixels[i].y(), layout.MapY(y[i]), kPixelTolerance) << i;
    EXPECT_GT(pixels[i].x(), layout.left);
    EXPECT_LT(pixels[i].x(), layout.left + layout.width);
    EXPECT_GT(pixels[i].y(), layout.top);
    EXPECT_LT(pixels[i].y(), layout.top + layout.height);
  }
  // x = 0 is 0.5 / 11 of the width from the left edge; the largest y is highest on screen.
  EXPECT_NEAR(pixels[0].x(), layout.left + layout.width * 0.5 / 11.0, kPixelTolerance);
  EXPECT_NEAR(pixels[1].y(), layout.top + layout.height * 0.2 / 4.4, kPixelTolerance);
  EXPECT_LT(pixels[1].y(), pixels[2].y());
  EXPECT_LT(pixels[2].y(), pixels[0].y());
}

TEST(SvgFigure, PanelsAreLaidOutInRows) {
  const FigureOptions options{.columns = 2, .panel_width = 300, .panel_height = 200};
  const Panel panel = LinePanel({0, 1}, {0, 1});
  const std::string svg = Figure({panel, panel, panel}, options);
  const std::vector<std::string> lines = Tags(svg, "<polyline class=\"line\"");
  ASSERT_EQ(lines.size(), 3u);
  for (std::size_t index = 0; index < 3; ++index) {
    const PanelLayout layout = LayoutPanel(panel, index, options);
    const double column = static_cast<double>(index % 2), row = static_cast<double>(index / 2);
    EXPECT_GT(layout.left, 300.0 * column);
    EXPECT_LT(layout.left + layout.width, 300.0 * (column + 1));
    EXPECT_GT(layout.top, 200.0 * row);
    EXPECT_LT(layout.top + layout.height, 200.0 * (row + 1));
    const std::vector<Eigen::Vector2d> pixels = PointsOf(lines[index]);
    ASSERT_EQ(pixels.size(), 2u);
    EXPECT_NEAR(pixels[0].x(), layout.MapX(0.0), kPixelTolerance);
    EXPECT_NEAR(pixels[1].y(), layout.MapY(1.0), kPixelTolerance);
  }
  const std::string root = Tags(svg, "<svg ").at(0);
  EXPECT_EQ(AttributeOf(root, "width"), "600");
  EXPECT_EQ(AttributeOf(root, "height"), "400");
}

// The ellipse polygon of panel 0 in data coordinates.
std::vector<Eigen::Vector2d> EllipseInData(const Panel& panel) {
  const PanelLayout layout = LayoutPanel(panel, 0, FigureOptions{});
  const std::string svg = Figure({panel}, FigureOptions{});
  std::vector<Eigen::Vector2d> points;
  for (const Eigen::Vector2d& p : PointsOf(Tags(svg, "<polygon class=\"ellipse\"").at(0))) {
    points.emplace_back(layout.UnmapX(p.x()), layout.UnmapY(p.y()));
  }
  return points;
}

TEST(SvgFigure, AxisAlignedEllipseHasSemiAxesScaleTimesSqrtEigenvalues) {
  const Eigen::Matrix2d covariance = Eigen::Vector2d(4.0, 1.0).asDiagonal();
  const EllipseAxes axes = AxesOf(covariance, 2.0);
  EXPECT_NEAR(axes.major, 4.0, 1e-12);
  EXPECT_NEAR(axes.minor, 2.0, 1e-12);
  EXPECT_NEAR(axes.angle, 0.0, 1e-12);
  EXPECT_NEAR(AxesOf(Eigen::Vector2d(1.0, 4.0).asDiagonal(), 2.0).angle, std::numbers::pi / 2,
              1e-12);

  Panel panel;
  const Eigen::Vector2d centre(1.0, -3.0);
  panel.ellipses.push_back({.label = "2σ", .centre = centre, .covariance = covariance});
  // The axis ranges cover the ellipse: x in centre ± 4, y in centre ± 2.
  const PanelLayout layout = LayoutPanel(panel, 0, FigureOptions{});
  EXPECT_NEAR(layout.x.lo, -3.0 - 0.4, 1e-9);
  EXPECT_NEAR(layout.x.hi, 5.0 + 0.4, 1e-9);
  EXPECT_NEAR(layout.y.lo, -5.0 - 0.2, 1e-9);
  EXPECT_NEAR(layout.y.hi, -1.0 + 0.2, 1e-9);

  const std::vector<Eigen::Vector2d> points = EllipseInData(panel);
  ASSERT_GE(points.size(), 16u);
  double longest = 0.0, shortest = 1e9;
  Eigen::Vector2d far_direction, near_direction;
  for (const Eigen::Vector2d& p : points) {
    const Eigen::Vector2d d = p - centre;
    // Every vertex lies on the ellipse (x/4)² + (y/2)² = 1.
    EXPECT_NEAR(std::pow(d.x() / 4.0, 2) + std::pow(d.y() / 2.0, 2), 1.0, 2e-3);
    if (d.norm() > longest) longest = d.norm(), far_direction = d.normalized();
    if (d.norm() < shortest) shortest = d.norm(), near_direction = d.normalized();
  }
  EXPECT_NEAR(longest, 4.0, 2e-3);
  EXPECT_NEAR(shortest, 2.0, 2e-3);
  EXPECT_NEAR(longest / shortest, 2.0, 2e-3);
  EXPECT_NEAR(std::abs(far_direction.x()), 1.0, 1e-4);
  EXPECT_NEAR(std::abs(near_direction.y()), 1.0, 1e-4);
}

TEST(SvgFigure, RotatedCovarianceGivesTheEigenvectorAngle) {
  for (const double degrees : {30.0, -60.0, 75.0, 120.0}) {
    const double angle = degrees * std::numbers::pi / 180.0;
    const Eigen::Matrix2d rotation = Eigen::Rotation2Dd(angle).toRotationMatrix();
    const Eigen::Matrix2d covariance =
        rotation * Eigen::Vector2d(9.0, 1.0).asDiagonal() * rotation.transpose();
    const EllipseAxes axes = AxesOf(covariance, 1.0);
    // The angle of the major axis, as a line: modulo 180° into (-90°, 90°].
    const double expected = degrees > 90.0 ? angle - std::numbers::pi : angle;
    EXPECT_NEAR(axes.angle, expected, 1e-9) << degrees;
    EXPECT_NEAR(axes.major, 3.0, 1e-9);
    EXPECT_NEAR(axes.minor, 1.0, 1e-9);

    Panel panel;
    panel.ellipses.push_back({.centre = {0.0, 0.0}, .covariance = covariance, .scale = 1.0});
    double longest = 0.0, drawn_angle = 0.0;
    for (const Eigen::Vector2d& p : EllipseInData(panel)) {
      if (p.norm() > longest) longest = p.norm(), drawn_angle = std::atan(p.y() / p.x());
    }
    EXPECT_NEAR(longest, 3.0, 2e-3) << degrees;
    EXPECT_NEAR(drawn_angle, expected, 1e-3) << degrees;
  }
}

TEST(SvgFigure, NonFiniteValuesBreakLinesAndAreSkipped) {
  Panel panel = LinePanel({0, 1, 2, 3, 4, 5, 6, 7}, {0, 1, kNaN, 3, 4, kInf, 6, 7});
  panel.lines[0].x[7] = kNaN;                                  // vertex 7 goes too
  panel.lines.push_back({.x = {0, kNaN, 2}, .y = {5, 5, 5}});  // two isolated vertices
  panel.points.push_back({.xy = {{kNaN, 1.0}, {1.0, -kInf}}});
  panel.ellipses.push_back({.centre = {kNaN, 0.0}});
  const PanelLayout layout = LayoutPanel(panel, 0, FigureOptions{});
  EXPECT_DOUBLE_EQ(layout.x.lo, -0.3);
  EXPECT_DOUBLE_EQ(layout.x.hi, 6.3);
  EXPECT_DOUBLE_EQ(layout.y.lo, -0.3);
  EXPECT_DOUBLE_EQ(layout.y.hi, 6.3);

  const std::string svg = Figure({panel}, FigureOptions{});
  EXPECT_EQ(CheckXml(svg), "");
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
  const std::vector<std::string> lines = Tags(svg, "<polyline class=\"line\"");
  ASSERT_EQ(lines.size(), 2u);
  const std::vector<Eigen::Vector2d> first = PointsOf(lines[0]), second = PointsOf(lines[1]);
  ASSERT_EQ(first.size(), 2u);
  ASSERT_EQ(second.size(), 2u);
  EXPECT_NEAR(first[1].x(), layout.MapX(1.0), kPixelTolerance);
  EXPECT_NEAR(second[0].x(), layout.MapX(3.0), kPixelTolerance);
  EXPECT_NEAR(second[1].y(), layout.MapY(4.0), kPixelTolerance);
  // Vertex 6 stands alone between inf and NaN, and so do both vertices of the second line.
  EXPECT_EQ(Tags(svg, "<circle class=\"line-dot\"").size(), 3u);
  EXPECT_EQ(Tags(svg, "<polygon class=\"ellipse\"").size(), 0u);
  EXPECT_EQ(svg.find("<circle cx"), std::string::npos);  // no finite scatter point
}

TEST(SvgTicks, NiceStepsAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(NiceStep(1.0, 5), 0.2);
  EXPECT_DOUBLE_EQ(NiceStep(7.0, 5), 1.0);
  EXPECT_DOUBLE_EQ(NiceStep(130.0, 5), 20.0);
  EXPECT_DOUBLE_EQ(NiceStep(180.0, 5), 50.0);
  EXPECT_DOUBLE_EQ(NiceStep(0.037, 4), 0.01);
  EXPECT_DOUBLE_EQ(NiceStep(9.0, 1), 10.0);

  const std::vector<double> unit = NiceTicks(0.0, 1.0, 5).values;
  ASSERT_EQ(unit.size(), 6u);
  for (std::size_t i = 0; i < unit.size(); ++i) {
    EXPECT_NEAR(unit[i], 0.2 * static_cast<double>(i), 1e-12);
  }
  EXPECT_EQ(NiceTicks(-0.37, 2.9, 5).values, (std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0, 2.5}));
  EXPECT_EQ(NiceTicks(-0.37, 2.9, 2).values, (std::vector<double>{0.0, 2.0}));
  EXPECT_EQ(NiceTicks(-0.37, 2.9, 7).values, (std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0, 2.5}));
  // A step of 5e4 would give no tick in [0.04, 45000.04]: 2e4 gives two.
  const Ticks few = NiceTicks(0.04, 45000.04, 1);
  EXPECT_DOUBLE_EQ(few.step, 2e4);
  EXPECT_EQ(few.values, (std::vector<double>{2e4, 4e4}));
  EXPECT_TRUE(NiceTicks(1.0, 1.0, 5).values.empty());
  EXPECT_TRUE(NiceTicks(0.0, kInf, 5).values.empty());

  for (double lo = -7.3e-3; lo < 1e5; lo = lo * -3.7 + 0.011) {
    for (const double span : {1e-6, 0.003, 0.71, 9.99, 123.0, 4.5e4}) {
      for (const int target : {2, 4, 6}) {
        const double hi = lo + span;
        EXPECT_LE(span / NiceStep(span, target), 1.59 * target);
        EXPECT_GE(span / NiceStep(span, target), 0.63 * target);
        const Ticks nice = NiceTicks(lo, hi, target);
        const double step = nice.step;
        const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
        EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
                    std::abs(mantissa - 5) < 1e-9)
            << step;
        const std::vector<double>& ticks = nice.values;
        EXPECT_GE(ticks.size(), 2u) << lo << " " << hi;
        EXPECT_LE(ticks.size(), static_cast<std::size_t>(2 * target + 1)) << lo << " " << hi;
        for (std::size_t i = 0; i < ticks.size(); ++i) {
          EXPECT_GE(ticks[i], lo - 1e-9 * step);
          EXPECT_LE(ticks[i], hi + 1e-9 * step);
          const double k = ticks[i] / step;
          EXPECT_NEAR(k, std::round(k), 1e-6 + 1e-12 * std::abs(k));
          if (i > 0) {
            EXPECT_NEAR(ticks[i] - ticks[i - 1], step, 1e-9 * std::abs(lo) + 1e-12);
          }
        }
      }
    }
    if (std::abs(lo) > 1e5) break;
  }
}

TEST(SvgTicks, LabelsAreCompact) {
  EXPECT_EQ(FormatTick(0.1 + 0.2, 0.1), "0.3");
  EXPECT_EQ(FormatTick(-0.0, 1.0), "0");
  EXPECT_EQ(FormatTick(1e-17, 0.1), "0");
  EXPECT_EQ(FormatTick(2.5, 0.5), "2.5");
  EXPECT_EQ(FormatTick(-0.25, 0.05), "-0.25");
  EXPECT_EQ(FormatTick(10.0, 5.0), "10");
  EXPECT_EQ(FormatTick(300.0, 100.0), "300");
  EXPECT_EQ(FormatTick(1.5e6, 5e5), "1.5e6");
  EXPECT_EQ(FormatTick(2e-5, 1e-5), "2e-5");
  EXPECT_EQ(FormatTick(-3e-5, 1e-5), "-3e-5");

  // The figure labels exactly its layout's ticks.
  const Panel panel = LinePanel({0, 0.7}, {-0.37, 2.9});
  const PanelLayout layout = LayoutPanel(panel, 0, FigureOptions{});
  std::vector<std::string> expected;
  for (const double tick : layout.x_ticks.values) {
    expected.push_back(FormatTick(tick, layout.x_ticks.step));
  }
  for (const double tick : layout.y_ticks.values) {
    expected.push_back(FormatTick(tick, layout.y_ticks.step));
  }
  EXPECT_EQ(Texts(Figure({panel}, FigureOptions{}), "tick-label"), expected);
  EXPECT_GE(layout.x_ticks.values.size(), 2u);
  EXPECT_GE(layout.y_ticks.values.size(), 2u);
}

TEST(SvgFigure, DegenerateRangesStillGiveValidAxes) {
  EXPECT_DOUBLE_EQ(DataRange({2.0, 2.0, 2.0}).lo, 1.8);
  EXPECT_DOUBLE_EQ(DataRange({2.0, 2.0, 2.0}).hi, 2.2);
  EXPECT_DOUBLE_EQ(DataRange({0.0}).lo, -1.0);
  EXPECT_DOUBLE_EQ(DataRange({0.0}).hi, 1.0);
  EXPECT_DOUBLE_EQ(DataRange({kNaN}).lo, 0.0);
  EXPECT_DOUBLE_EQ(DataRange({}).hi, 1.0);

  for (const Panel& panel : {LinePanel({1, 1, 1}, {2, 2, 2}), LinePanel({0, 0}, {0, 0}), Panel{},
                             LinePanel({-5e-9, -5e-9}, {3e7, 3e7})}) {
    const PanelLayout layout = LayoutPanel(panel, 0, FigureOptions{});
    EXPECT_LT(layout.x.lo, layout.x.hi);
    EXPECT_LT(layout.y.lo, layout.y.hi);
    EXPECT_GE(layout.x_ticks.values.size(), 2u);
    EXPECT_GE(layout.y_ticks.values.size(), 2u);
    const std::string svg = Figure({panel}, FigureOptions{});
    EXPECT_EQ(CheckXml(svg), "");
    EXPECT_EQ(svg.find("nan"), std::string::npos);
    for (const std::string& label : Texts(svg, "tick-label")) EXPECT_LE(label.size(), 8u) << label;
    for (const std::string& line : Tags(svg, "<polyline class=\"line\"")) {
      for (const Eigen::Vector2d& p : PointsOf(line)) {
        EXPECT_NEAR(p.x(), layout.left + 0.5 * layout.width, kPixelTolerance);
        EXPECT_NEAR(p.y(), layout.top + 0.5 * layout.height, kPixelTolerance);
      }
    }
  }
}

TEST(SvgFigure, LegendListsEachNonEmptyLabelOnce) {
  Panel panel = FullPanel();
  panel.lines.push_back({.label = "mean", .x = {1, 2}, .y = {0, 0}});
  panel.lines.push_back({.label = "", .x = {1, 2}, .y = {1, 1}});
  panel.ellipses.push_back({.label = "samples", .centre = {1.0, 1.0}});
  const std::string svg = Figure({panel}, FigureOptions{});
  EXPECT_EQ(CheckXml(svg), "");
  EXPECT_EQ(Texts(svg, "legend-label"),
            (std::vector<std::string>{"mean", "mean ± 2σ", "samples", "truth", "2σ"}));
  // One sample per entry, styled like its element: the dashed line's sample is dashed.
  const std::vector<std::string> samples = Tags(svg, "class=\"legend-sample\"");
  ASSERT_EQ(samples.size(), 5u);
  EXPECT_EQ(AttributeOf(samples[0], "stroke-dasharray"), "");
  EXPECT_NE(AttributeOf(samples[1], "stroke-dasharray"), "");
  EXPECT_NE(samples[4].find("#d62728"), std::string::npos);

  // Data along the top edge pushes the legend to a bottom corner.
  Panel high = LinePanel({0, 1, 2, 3, 4}, {1, 1, 1, 1, 1});
  high.lines.push_back({.x = {0, 4}, .y = {0.5, 0}});  // ends in the bottom-right corner
  const PanelLayout layout = LayoutPanel(high, 0, FigureOptions{});
  const std::string box = Tags(Figure({high}, FigureOptions{}), "<rect class=\"legend-box\"").at(0);
  EXPECT_GT(NumberOf(box, "y"), layout.top + 0.5 * layout.height);
  EXPECT_LT(NumberOf(box, "x"), layout.left + 0.5 * layout.width);

  panel.legend = false;
  EXPECT_EQ(Texts(Figure({panel}, FigureOptions{}), "legend-label").size(), 0u);
  EXPECT_EQ(Texts(Figure({LinePanel({0, 1}, {0, 1})}, FigureOptions{}), "legend-label").size(), 1u);
  Panel unlabelled = LinePanel({0, 1}, {0, 1});
  unlabelled.lines[0].label.clear();
  EXPECT_EQ(Figure({unlabelled}, FigureOptions{}).find("class=\"legend\""), std::string::npos);
}

TEST(FigureOptions, IsValidNamesTheField) {
  using hecal::testing::RefusesNaming;
  const FigureOptions defaults;
  EXPECT_TRUE(hecal::testing::IsValidOptions(defaults));
  EXPECT_TRUE(RefusesNaming(defaults, "FigureOptions.columns", [](auto& o) { o.columns = 0; }));
  EXPECT_TRUE(RefusesNaming(defaults, "FigureOptions.panel_width",
                            [](auto& o) { o.panel_width = FigureOptions::kMinPanelWidth - 1; }));
  EXPECT_TRUE(RefusesNaming(defaults, "FigureOptions.panel_height",
                            [](auto& o) { o.panel_height = FigureOptions::kMinPanelHeight - 1; }));
}

}  // namespace
}  // namespace hecal::report::svg
