#include "hecal/report/svg_figure.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <string>
#include <system_error>

#include "hecal/core/options_check.h"

namespace hecal::report::svg {
namespace {

// Layout in pixels.
constexpr double kFigureTitleHeight = 30.0;
constexpr double kPanelTitleHeight = 28.0;
constexpr double kPlotRight = 14.0;
constexpr double kPlotBottom = 44.0;
constexpr double kTickLength = 4.0;
constexpr double kTickCharWidth = 6.0;    // approximate advance of a 10px digit
constexpr double kLegendCharWidth = 5.8;  // approximate advance of a 10px character
constexpr double kLegendRowHeight = 14.0;
constexpr int kEllipseVertices = 96;  // a multiple of 4: the axis end points are vertices
constexpr double kMargin = 0.05;      // of the data span, on each side

std::string ToChars(double value, std::chars_format format, int precision) {
  char buffer[64];
  const std::to_chars_result result =
      std::to_chars(buffer, buffer + sizeof(buffer), value, format, precision);
  if (result.ec != std::errc()) return "0";
  return std::string(buffer, result.ptr);
}

// "-0", "-0.00" and the like are zero.
void DropNegativeZero(std::string& text) {
  if (text.empty() || text[0] != '-') return;
  const bool all_zero =
      std::all_of(text.begin() + 1, text.end(), [](char c) { return c == '0' || c == '.'; });
  if (all_zero) text.erase(0, 1);
}

// out += a + b + …, without temporaries (and without GCC 12's -Wrestrict false positive on
// "literal" + std::string).
template <typename... Parts>
void Append(std::string& out, const Parts&... parts) {
  (out.append(parts), ...);
}

// A pixel coordinate: at most 2 decimals, trailing zeros dropped.
std::string Px(double value) {
  if (!std::isfinite(value)) return "0";
  std::string text = ToChars(value, std::chars_format::fixed, 2);
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  DropNegativeZero(text);
  return text;
}

std::string Transform(double x, double y) {
  std::string text;
  Append(text, " transform=\"translate(", Px(x), " ", Px(y), ") rotate(-90)\"");
  return text;
}

std::string Attr(std::string_view name, double value) {
  std::string text = " ";
  text += name;
  text += "=\"";
  text += Px(value);
  text += '"';
  return text;
}

std::string Attr(std::string_view name, std::string_view value) {
  std::string text = " ";
  text += name;
  text += "=\"";
  text += EscapeXml(value);
  text += '"';
  return text;
}

// Number of characters (UTF-8 code points) of `text`, for width estimates.
std::size_t Glyphs(std::string_view text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0u) != 0x80u;
  }));
}

bool Finite(const Eigen::Vector2d& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y());
}

bool Finite(const Ellipse& e) {
  return Finite(e.centre) && e.covariance.allFinite() && std::isfinite(e.scale);
}

// Unit vectors along the major and minor axes with AxesOf's lengths.
struct EllipseFrame {
  EllipseAxes axes;
  Eigen::Vector2d u = Eigen::Vector2d::UnitX(), v = Eigen::Vector2d::UnitY();
};

EllipseFrame FrameOf(const Eigen::Matrix2d& covariance, double scale) {
  const Eigen::Matrix2d symmetric = 0.5 * (covariance + covariance.transpose());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(symmetric);
  const Eigen::Vector2d values = solver.eigenvalues().cwiseMax(0.0);  // ascending
  EllipseFrame frame;
  frame.u = solver.eigenvectors().col(1);
  frame.v = Eigen::Vector2d(-frame.u.y(), frame.u.x());
  const double k = std::abs(scale);
  frame.axes.major = k * std::sqrt(values(1));
  frame.axes.minor = k * std::sqrt(values(0));
  double angle = std::atan2(frame.u.y(), frame.u.x());
  if (angle <= -std::numbers::pi / 2) angle += std::numbers::pi;
  if (angle > std::numbers::pi / 2) angle -= std::numbers::pi;
  frame.axes.angle = angle;
  return frame;
}

std::vector<Eigen::Vector2d> EllipseVertices(const Ellipse& ellipse) {
  const EllipseFrame frame = FrameOf(ellipse.covariance, ellipse.scale);
  std::vector<Eigen::Vector2d> vertices;
  vertices.reserve(kEllipseVertices);
  for (int i = 0; i < kEllipseVertices; ++i) {
    const double t = 2.0 * std::numbers::pi * static_cast<double>(i) / kEllipseVertices;
    vertices.push_back(ellipse.centre + frame.axes.major * std::cos(t) * frame.u +
                       frame.axes.minor * std::sin(t) * frame.v);
  }
  return vertices;
}

std::string DashAttr(bool dashed, double width) {
  if (!dashed) return "";
  const double w = std::max(width, 0.5);
  std::string text;
  Append(text, " stroke-dasharray=\"", Px(4.0 * w), " ", Px(2.5 * w), "\"");
  return text;
}

int ColumnCount(std::size_t panels, const FigureOptions& options) {
  if (panels == 0) return 1;
  return static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(options.columns), panels));
}

double PanelWidth(const FigureOptions& options) {
  return static_cast<double>(options.panel_width);
}
double PanelHeight(const FigureOptions& options) {
  return static_cast<double>(options.panel_height);
}
double TitleHeight(const FigureOptions& options) {
  return options.title.empty() ? 0.0 : kFigureTitleHeight;
}

// Top-left corner of panel `index` in figure pixels.
Eigen::Vector2d PanelOrigin(std::size_t index, const FigureOptions& options) {
  const std::size_t columns = static_cast<std::size_t>(options.columns);
  return {PanelWidth(options) * static_cast<double>(index % columns),
          TitleHeight(options) + PanelHeight(options) * static_cast<double>(index / columns)};
}

class Writer {
 public:
  explicit Writer(std::string& out) : out_(out) {}

  void Text(double x, double y, std::string_view text, std::string_view css_class, double size,
            std::string_view anchor, std::string_view extra = "") {
    Append(out_, "<text", Attr("class", css_class), Attr("x", x), Attr("y", y),
           Attr("font-size", size), Attr("text-anchor", anchor));
    out_ += extra;
    Append(out_, ">", EscapeXml(text), "</text>\n");
  }

  void Segment(double x1, double y1, double x2, double y2, std::string_view css_class,
               std::string_view stroke, double width, std::string_view extra = "") {
    Append(out_, "<line", Attr("class", css_class), Attr("x1", x1), Attr("y1", y1), Attr("x2", x2),
           Attr("y2", y2), Attr("stroke", stroke), Attr("stroke-width", width));
    out_ += extra;
    out_ += "/>\n";
  }

  void Marker(Points::Marker marker, double x, double y, double size) {
    switch (marker) {
      case Points::Marker::kDot:
      case Points::Marker::kCircle:
        Append(out_, "<circle", Attr("cx", x), Attr("cy", y), Attr("r", size), "/>");
        break;
      case Points::Marker::kCross:
        Append(out_, "<path d=\"M", Px(x - size), " ", Px(y - size), "L", Px(x + size), " ",
               Px(y + size), "M", Px(x - size), " ", Px(y + size), "L", Px(x + size), " ",
               Px(y - size), "\"/>");
        break;
    }
  }

  // A <g> whose children inherit the style of `points`.
  void OpenPointsGroup(const Points& points, std::string_view css_class) {
    Append(out_, "<g", Attr("class", css_class));
    if (points.marker == Points::Marker::kDot) {
      Append(out_, Attr("fill", points.color), " stroke=\"none\"");
    } else {
      Append(out_, " fill=\"none\"", Attr("stroke", points.color),
             Attr("stroke-width", std::max(1.0, 0.5 * points.size)));
    }
    if (points.opacity < 1.0) out_ += Attr("opacity", std::clamp(points.opacity, 0.0, 1.0));
    out_ += ">";
  }

  std::string& out() { return out_; }

 private:
  std::string& out_;
};

// Everything a panel contributes to the axis ranges.
void CollectExtent(const Panel& panel, std::vector<double>& xs, std::vector<double>& ys) {
  for (const Line& line : panel.lines) {
    const std::size_t n = std::min(line.x.size(), line.y.size());
    for (std::size_t i = 0; i < n; ++i) {
      if (std::isfinite(line.x[i]) && std::isfinite(line.y[i])) {
        xs.push_back(line.x[i]);
        ys.push_back(line.y[i]);
      }
    }
  }
  for (const Points& points : panel.points) {
    for (const Eigen::Vector2d& p : points.xy) {
      if (Finite(p)) {
        xs.push_back(p.x());
        ys.push_back(p.y());
      }
    }
  }
  for (const Ellipse& ellipse : panel.ellipses) {
    if (!Finite(ellipse)) continue;
    const EllipseFrame frame = FrameOf(ellipse.covariance, ellipse.scale);
    const double a = frame.axes.major, b = frame.axes.minor;
    const double half_x = std::hypot(a * frame.u.x(), b * frame.v.x());
    const double half_y = std::hypot(a * frame.u.y(), b * frame.v.y());
    xs.push_back(ellipse.centre.x() - half_x);
    xs.push_back(ellipse.centre.x() + half_x);
    ys.push_back(ellipse.centre.y() - half_y);
    ys.push_back(ellipse.centre.y() + half_y);
  }
}

// Pixel positions along everything the panel draws (line segments sampled), for placing the
// legend where it hides the least.
std::vector<Eigen::Vector2d> DataPixels(const Panel& panel, const PanelLayout& layout) {
  std::vector<Eigen::Vector2d> pixels;
  const auto map = [&](const Eigen::Vector2d& p) {
    return Eigen::Vector2d(layout.MapX(p.x()), layout.MapY(p.y()));
  };
  for (const Line& line : panel.lines) {
    const std::size_t n = std::min(line.x.size(), line.y.size());
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector2d p(line.x[i], line.y[i]);
      if (!Finite(p)) continue;
      pixels.push_back(map(p));
      if (i + 1 < n && Finite(Eigen::Vector2d(line.x[i + 1], line.y[i + 1]))) {
        const Eigen::Vector2d q = map(Eigen::Vector2d(line.x[i + 1], line.y[i + 1]));
        for (int k = 1; k < 8; ++k) {
          pixels.push_back(pixels.back() + (q - map(p)) / 8.0);
        }
      }
    }
  }
  for (const Points& points : panel.points) {
    for (const Eigen::Vector2d& p : points.xy) {
      if (Finite(p)) pixels.push_back(map(p));
    }
  }
  for (const Ellipse& ellipse : panel.ellipses) {
    if (!Finite(ellipse)) continue;
    for (const Eigen::Vector2d& p : EllipseVertices(ellipse)) pixels.push_back(map(p));
  }
  return pixels;
}

void WriteLegend(Writer& w, const Panel& panel, const PanelLayout& layout) {
  enum class Kind { kLine, kPoints, kEllipse };
  struct Entry {
    Kind kind;
    std::size_t index;
    const std::string* label;
  };
  std::vector<Entry> entries;
  std::set<std::string> seen;
  auto add = [&](Kind kind, std::size_t index, const std::string& label) {
    if (!label.empty() && seen.insert(label).second) entries.push_back({kind, index, &label});
  };
  for (std::size_t i = 0; i < panel.lines.size(); ++i) add(Kind::kLine, i, panel.lines[i].label);
  for (std::size_t i = 0; i < panel.points.size(); ++i) {
    add(Kind::kPoints, i, panel.points[i].label);
  }
  for (std::size_t i = 0; i < panel.ellipses.size(); ++i) {
    add(Kind::kEllipse, i, panel.ellipses[i].label);
  }
  if (entries.empty()) return;

  std::size_t longest = 0;
  for (const Entry& entry : entries) longest = std::max(longest, Glyphs(*entry.label));
  const double box_width = 34.0 + kLegendCharWidth * static_cast<double>(longest);
  const double box_height = 6.0 + kLegendRowHeight * static_cast<double>(entries.size());
  // The corner (top-right, top-left, bottom-right, bottom-left) covering the fewest data.
  const std::vector<Eigen::Vector2d> drawn = DataPixels(panel, layout);
  double box_left = 0.0, box_top = 0.0;
  std::size_t fewest = std::numeric_limits<std::size_t>::max();
  for (const bool top : {true, false}) {
    for (const bool right : {true, false}) {
      const double x = right ? layout.left + layout.width - 6.0 - box_width : layout.left + 6.0;
      const double y = top ? layout.top + 6.0 : layout.top + layout.height - 6.0 - box_height;
      const std::size_t covered =
          static_cast<std::size_t>(std::count_if(drawn.begin(), drawn.end(), [&](const auto& p) {
            return p.x() >= x - 3.0 && p.x() <= x + box_width + 3.0 && p.y() >= y - 3.0 &&
                   p.y() <= y + box_height + 3.0;
          }));
      if (covered < fewest) {
        fewest = covered;
        box_left = x;
        box_top = y;
      }
    }
  }
  std::string& out = w.out();
  Append(out, "<g class=\"legend\">\n<rect class=\"legend-box\"", Attr("x", box_left),
         Attr("y", box_top), Attr("width", box_width), Attr("height", box_height),
         " fill=\"#ffffff\" fill-opacity=\"0.85\" stroke=\"#bbbbbb\" stroke-width=\"0.8\"/>\n");
  for (std::size_t row = 0; row < entries.size(); ++row) {
    const Entry& entry = entries[row];
    const double y = box_top + 3.0 + kLegendRowHeight * (static_cast<double>(row) + 0.5);
    const double x0 = box_left + 6.0, x1 = box_left + 24.0;
    switch (entry.kind) {
      case Kind::kLine: {
        const Line& line = panel.lines[entry.index];
        w.Segment(x0, y, x1, y, "legend-sample", line.color, line.width,
                  DashAttr(line.dashed, line.width));
        break;
      }
      case Kind::kPoints: {
        const Points& points = panel.points[entry.index];
        w.OpenPointsGroup(points, "legend-sample");
        w.Marker(points.marker, 0.5 * (x0 + x1), y, std::clamp(points.size, 2.0, 4.5));
        out += "</g>\n";
        break;
      }
      case Kind::kEllipse: {
        const Ellipse& ellipse = panel.ellipses[entry.index];
        Append(out, "<ellipse class=\"legend-sample\"", Attr("cx", 0.5 * (x0 + x1)), Attr("cy", y),
               Attr("rx", 8.0), Attr("ry", 4.0), " fill=\"none\"", Attr("stroke", ellipse.color),
               Attr("stroke-width", ellipse.width), DashAttr(ellipse.dashed, ellipse.width),
               "/>\n");
        break;
      }
    }
    w.Text(x1 + 5.0, y + 3.5, *entry.label, "legend-label", 10.0, "start");
  }
  out += "</g>\n";
}

void WritePanel(Writer& w, const Panel& panel, std::size_t index, const FigureOptions& options) {
  const PanelLayout layout = LayoutPanel(panel, index, options);
  std::string& out = w.out();
  std::string clip_id = "plot-clip-";
  clip_id += std::to_string(index);
  const double right = layout.left + layout.width, bottom = layout.top + layout.height;

  out += "<g class=\"panel\">\n";
  Append(out, "<defs><clipPath", Attr("id", clip_id), "><rect", Attr("x", layout.left),
         Attr("y", layout.top), Attr("width", layout.width), Attr("height", layout.height),
         "/></clipPath></defs>\n");
  Append(out, "<rect class=\"plot-area\"", Attr("x", layout.left), Attr("y", layout.top),
         Attr("width", layout.width), Attr("height", layout.height),
         " fill=\"#ffffff\" stroke=\"none\"/>\n");
  if (!panel.title.empty()) {
    w.Text(layout.left + 0.5 * layout.width, layout.top - 10.0, panel.title, "panel-title", 12.0,
           "middle", " font-weight=\"bold\"");
  }

  // Grid, ticks and tick labels.
  for (const double tick : layout.x_ticks.values) {
    const double x = layout.MapX(tick);
    w.Segment(x, layout.top, x, bottom, "grid", "#e6e6e6", 0.8);
    w.Segment(x, bottom, x, bottom + kTickLength, "tick", "#000000", 0.8);
    w.Text(x, bottom + kTickLength + 11.0, FormatTick(tick, layout.x_ticks.step), "tick-label",
           10.0, "middle");
  }
  for (const double tick : layout.y_ticks.values) {
    const double y = layout.MapY(tick);
    w.Segment(layout.left, y, right, y, "grid", "#e6e6e6", 0.8);
    w.Segment(layout.left - kTickLength, y, layout.left, y, "tick", "#000000", 0.8);
    w.Text(layout.left - kTickLength - 3.0, y + 3.5, FormatTick(tick, layout.y_ticks.step),
           "tick-label", 10.0, "end");
  }
  if (!panel.x_label.empty()) {
    w.Text(layout.left + 0.5 * layout.width, bottom + kTickLength + 30.0, panel.x_label,
           "axis-label", 11.0, "middle");
  }
  if (!panel.y_label.empty()) {
    const double x = PanelOrigin(index, options).x() + 14.0;
    const double y = layout.top + 0.5 * layout.height;
    w.Text(0.0, 0.0, panel.y_label, "axis-label", 11.0, "middle", Transform(x, y));
  }

  // Data, clipped to the plot area: points, then ellipses, then lines on top.
  Append(out, "<g class=\"data\" clip-path=\"url(#", clip_id, ")\">\n");
  for (const Points& points : panel.points) {
    w.OpenPointsGroup(points, "points");
    for (const Eigen::Vector2d& p : points.xy) {
      if (Finite(p)) w.Marker(points.marker, layout.MapX(p.x()), layout.MapY(p.y()), points.size);
    }
    out += "</g>\n";
  }
  for (const Ellipse& ellipse : panel.ellipses) {
    if (!Finite(ellipse)) continue;
    Append(out, "<polygon class=\"ellipse\" fill=\"none\"", Attr("stroke", ellipse.color),
           Attr("stroke-width", ellipse.width), DashAttr(ellipse.dashed, ellipse.width),
           " points=\"");
    bool first = true;
    for (const Eigen::Vector2d& p : EllipseVertices(ellipse)) {
      if (!first) out += ' ';
      first = false;
      Append(out, Px(layout.MapX(p.x())), ",", Px(layout.MapY(p.y())));
    }
    out += "\"/>\n";
  }
  for (const Line& line : panel.lines) {
    const std::size_t n = std::min(line.x.size(), line.y.size());
    std::size_t i = 0;
    while (i < n) {
      if (!std::isfinite(line.x[i]) || !std::isfinite(line.y[i])) {
        ++i;
        continue;
      }
      std::size_t end = i;
      while (end < n && std::isfinite(line.x[end]) && std::isfinite(line.y[end])) ++end;
      if (end - i == 1) {
        Append(out, "<circle class=\"line-dot\"", Attr("cx", layout.MapX(line.x[i])),
               Attr("cy", layout.MapY(line.y[i])), Attr("r", std::max(1.0, line.width)),
               Attr("fill", line.color), "/>\n");
      } else {
        Append(out, "<polyline class=\"line\" fill=\"none\"", Attr("stroke", line.color),
               Attr("stroke-width", line.width), DashAttr(line.dashed, line.width),
               " stroke-linejoin=\"round\" points=\"");
        for (std::size_t k = i; k < end; ++k) {
          if (k > i) out += ' ';
          Append(out, Px(layout.MapX(line.x[k])), ",", Px(layout.MapY(line.y[k])));
        }
        out += "\"/>\n";
      }
      i = end;
    }
  }
  out += "</g>\n";

  Append(out, "<rect class=\"frame\"", Attr("x", layout.left), Attr("y", layout.top),
         Attr("width", layout.width), Attr("height", layout.height),
         " fill=\"none\" stroke=\"#000000\" stroke-width=\"0.8\"/>\n");
  if (panel.legend) WriteLegend(w, panel, layout);
  out += "</g>\n";
}

}  // namespace

std::string EscapeXml(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        escaped += "&amp;";
        break;
      case '<':
        escaped += "&lt;";
        break;
      case '>':
        escaped += "&gt;";
        break;
      case '"':
        escaped += "&quot;";
        break;
      case '\'':
        escaped += "&apos;";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20u && c != '\t' && c != '\n') break;
        escaped += c;
    }
  }
  return escaped;
}

Range DataRange(const std::vector<double>& values) {
  bool any = false;
  double lo = 0.0, hi = 0.0;
  for (const double v : values) {
    if (!std::isfinite(v)) continue;
    lo = any ? std::min(lo, v) : v;
    hi = any ? std::max(hi, v) : v;
    any = true;
  }
  if (!any) return {0.0, 1.0};
  const double span = hi - lo;
  if (!std::isfinite(span)) return {lo, hi};  // overflowing span: no margin
  if (span == 0.0) {
    const double pad = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
    return {lo - pad, hi + pad};
  }
  return {lo - kMargin * span, hi + kMargin * span};
}

double NiceStep(double span, int target) {
  if (!(span > 0.0) || !std::isfinite(span)) return 1.0;
  const double raw = span / static_cast<double>(std::max(1, target));
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double normalised = raw / magnitude;  // in [1, 10)
  // The nearest of 1, 2, 5, 10 on a log scale.
  if (normalised < std::sqrt(2.0)) return magnitude;
  if (normalised < std::sqrt(10.0)) return 2.0 * magnitude;
  if (normalised < std::sqrt(50.0)) return 5.0 * magnitude;
  return 10.0 * magnitude;
}

Ticks NiceTicks(double lo, double hi, int target) {
  Ticks ticks;
  ticks.step = NiceStep(hi - lo, target);
  if (!(hi > lo) || !std::isfinite(hi - lo)) return ticks;
  for (int attempt = 0; attempt < 8; ++attempt) {
    const double step = ticks.step;
    const double first = std::ceil(lo / step - 1e-9);
    const double last = std::floor(hi / step + 1e-9);
    ticks.values.clear();
    if (last >= first && last - first <= 1000.0) {
      for (double k = first; k <= last; k += 1.0) {
        const double value = k * step;
        ticks.values.push_back(std::abs(value) < 1e-9 * step ? 0.0 : value);
      }
    }
    if (ticks.values.size() >= 2) break;
    // The next smaller nice step: 1 → 0.5, 2 → 1, 5 → 2 (× 10^k).
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    ticks.step = mantissa < 1.5 ? 0.5 * step : mantissa < 3.0 ? 0.5 * step : 0.4 * step;
  }
  return ticks;
}

std::string FormatTick(double value, double step) {
  if (!std::isfinite(value)) return "0";
  if (!(step > 0.0) || !std::isfinite(step)) step = std::abs(value) > 0.0 ? std::abs(value) : 1.0;
  if (std::abs(value) < 1e-6 * step) return "0";
  const int step_exponent = static_cast<int>(std::floor(std::log10(step) + 1e-9));
  const int value_exponent = static_cast<int>(std::floor(std::log10(std::abs(value)) + 1e-9));
  std::string text;
  if (value_exponent >= 6 || step_exponent <= -5) {
    const int digits = std::clamp(value_exponent - step_exponent, 0, 15);
    text = ToChars(value, std::chars_format::scientific, digits);
    // "1.5e+06" → "1.5e6", "2e-05" → "2e-5".
    const std::size_t e = text.find('e');
    if (e != std::string::npos) {
      const bool negative = text[e + 1] == '-';
      std::size_t d = e + 1;
      if (text[d] == '+' || text[d] == '-') ++d;
      while (d + 1 < text.size() && text[d] == '0') ++d;
      std::string compact = text.substr(0, e);
      Append(compact, "e", negative ? "-" : "", text.substr(d));
      text = compact;
    }
  } else {
    text = ToChars(value, std::chars_format::fixed, std::clamp(-step_exponent, 0, 15));
  }
  DropNegativeZero(text);
  return text;
}

EllipseAxes AxesOf(const Eigen::Matrix2d& covariance, double scale) {
  return FrameOf(covariance, scale).axes;
}

bool FigureOptions::IsValid(std::string* why) const {
  if (columns < 1) {
    return Invalid(why, "FigureOptions.columns",
                   "must be at least 1, got " + std::to_string(columns),
                   "give the number of panels per row");
  }
  if (panel_width < kMinPanelWidth) {
    return Invalid(why, "FigureOptions.panel_width",
                   "must be at least " + std::to_string(kMinPanelWidth) + " px, got " +
                       std::to_string(panel_width),
                   "give a wider panel (default 360)");
  }
  if (panel_height < kMinPanelHeight) {
    return Invalid(why, "FigureOptions.panel_height",
                   "must be at least " + std::to_string(kMinPanelHeight) + " px, got " +
                       std::to_string(panel_height),
                   "give a taller panel (default 260)");
  }
  return true;
}

PanelLayout LayoutPanel(const Panel& panel, std::size_t index, const FigureOptions& options) {
  RequireValid(options);
  std::vector<double> xs, ys;
  CollectExtent(panel, xs, ys);
  PanelLayout layout;
  layout.x = DataRange(xs);
  layout.y = DataRange(ys);

  const double panel_width = PanelWidth(options), panel_height = PanelHeight(options);
  const Eigen::Vector2d origin = PanelOrigin(index, options);
  const double panel_x = origin.x(), panel_y = origin.y();

  layout.top = panel_y + kPanelTitleHeight;
  layout.height = std::max(10.0, panel_height - kPanelTitleHeight - kPlotBottom);
  const int y_target = std::max(2, static_cast<int>(layout.height / 45.0));
  layout.y_ticks = NiceTicks(layout.y.lo, layout.y.hi, y_target);

  // The left margin fits the y label and the widest y tick label.
  std::size_t widest = 1;
  for (const double tick : layout.y_ticks.values) {
    widest = std::max(widest, FormatTick(tick, layout.y_ticks.step).size());
  }
  const double left_margin = (panel.y_label.empty() ? 8.0 : 24.0) + kTickLength + 5.0 +
                             kTickCharWidth * static_cast<double>(widest);
  layout.left = panel_x + left_margin;
  layout.width = std::max(10.0, panel_width - left_margin - kPlotRight);
  const int x_target = std::max(2, static_cast<int>(layout.width / 70.0));
  layout.x_ticks = NiceTicks(layout.x.lo, layout.x.hi, x_target);
  return layout;
}

std::string Figure(const std::vector<Panel>& panels, const FigureOptions& options) {
  RequireValid(options);
  const int columns = ColumnCount(panels.size(), options);
  const std::size_t rows = panels.empty()
                               ? 1
                               : (panels.size() + static_cast<std::size_t>(columns) - 1) /
                                     static_cast<std::size_t>(columns);
  const double width = PanelWidth(options) * static_cast<double>(columns);
  const double height = TitleHeight(options) + PanelHeight(options) * static_cast<double>(rows);

  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  Append(out, "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\"", Attr("width", width),
         Attr("height", height), " viewBox=\"0 0 ", Px(width), " ", Px(height),
         "\" font-family=\"Helvetica, Arial, sans-serif\">\n");
  Append(out, "<rect class=\"background\" x=\"0\" y=\"0\"", Attr("width", width),
         Attr("height", height), " fill=\"#ffffff\"/>\n");
  Writer w(out);
  if (!options.title.empty()) {
    w.Text(0.5 * width, 20.0, options.title, "figure-title", 15.0, "middle",
           " font-weight=\"bold\"");
  }
  for (std::size_t i = 0; i < panels.size(); ++i) WritePanel(w, panels[i], i, options);
  out += "</svg>\n";
  return out;
}

}  // namespace hecal::report::svg
