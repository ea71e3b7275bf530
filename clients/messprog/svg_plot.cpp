// Writing the SVG text.
#include "svg_plot.hpp"

#include "number_text.hpp"
#include "plot_geometry.hpp"

namespace imess::messprog {
namespace {

constexpr double kPanel = 400;                         // plot area, px square
constexpr double kLeft = 70, kRight = 30, kTop = 50;   // margins around it
constexpr double kViewWidth = kLeft + kPanel + kRight;
constexpr double kWidth = 2 * kViewWidth;
constexpr double kLegendTop = kTop + kPanel + 80;
constexpr double kHeight = kLegendTop + 40;

constexpr const char* kFeedColour = "#1f4e9c";
constexpr const char* kRapidColour = "#e8590c";
constexpr const char* kProbeColour = "#2b9348";

std::string px(double v) { return fixed(v, 2); }

std::string escaped(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string stroke_style(MoveKind kind) {
  switch (kind) {
    case MoveKind::Feed: return std::string("class=\"feed\" stroke=\"") + kFeedColour + "\" stroke-width=\"1.2\"";
    case MoveKind::Rapid:
      return std::string("class=\"rapid\" stroke=\"") + kRapidColour + "\" stroke-width=\"1\" stroke-dasharray=\"6 4\"";
    case MoveKind::Probe: return std::string("class=\"probe\" stroke=\"") + kProbeColour + "\" stroke-width=\"1.6\"";
  }
  return "";
}

std::string unit(const planner::Machine& m, int axis) {
  return m.axes[axis].kind == planner::AxisKind::Rotary ? "deg" : "mm";
}

std::string text(double x, double y, std::string_view s, std::string_view extra = {}) {
  return "<text x=\"" + px(x) + "\" y=\"" + px(y) + "\"" + (extra.empty() ? "" : " ") + std::string(extra) + ">" +
         escaped(s) + "</text>\n";
}

std::string line(double x1, double y1, double x2, double y2, std::string_view extra) {
  return "<line x1=\"" + px(x1) + "\" y1=\"" + px(y1) + "\" x2=\"" + px(x2) + "\" y2=\"" + px(y2) + "\" " +
         std::string(extra) + "/>\n";
}

// The frame's ticks, tick labels and axis names.
std::string axes_of(const ViewScale& s, const Panel& p, const planner::Machine& m, const ViewAxes& v) {
  std::string out;
  const double bottom = p.top + p.size, right = p.left + p.size;
  const auto th = ticks(s.h_lo(), s.h_hi());
  for (double t : th) {
    out += line(s.x(t), bottom, s.x(t), bottom + 5, "stroke=\"#555\"");
    out += text(s.x(t), bottom + 18, number_text(t, tick_decimals(th)), "text-anchor=\"middle\"");
  }
  const auto tv = ticks(s.v_lo(), s.v_hi());
  for (double t : tv) {
    out += line(p.left - 5, s.y(t), p.left, s.y(t), "stroke=\"#555\"");
    out += text(p.left - 8, s.y(t) + 4, number_text(t, tick_decimals(tv)), "text-anchor=\"end\"");
  }
  out += text((p.left + right) / 2, bottom + 36, std::string(1, m.axes[v.h].letter) + " [" + unit(m, v.h) + "]",
              "text-anchor=\"middle\" class=\"axis-name\"");
  const double yc = p.top + p.size / 2;
  out += text(p.left - 52, yc, std::string(1, m.axes[v.v].letter) + " [" + unit(m, v.v) + "]",
              "text-anchor=\"middle\" class=\"axis-name\" transform=\"rotate(-90 " + px(p.left - 52) + " " + px(yc) + ")\"");
  return out;
}

std::string box_text(const planner::Machine& m, int axis, const Range& r) {
  return std::string(1, m.axes[axis].letter) + " " + fixed(r.lo, 3) + " .. " + fixed(r.hi, 3) + " " + unit(m, axis);
}

std::string view_svg(const PathTrace& trace, const planner::Machine& m, const ViewAxes& v, double left) {
  const Panel p{left + kLeft, kTop, kPanel};
  std::string out = "<g id=\"" + v.id + "\" class=\"view\">\n";
  out += text(p.left, kTop - 16, v.title, "class=\"title\" font-size=\"15\" font-weight=\"bold\"");
  out += "<rect class=\"frame\" x=\"" + px(p.left) + "\" y=\"" + px(p.top) + "\" width=\"" + px(p.size) +
         "\" height=\"" + px(p.size) + "\" fill=\"none\" stroke=\"#555\"/>\n";
  if (v.v < 0) {
    out += text(p.left + p.size / 2, p.top + p.size / 2,
                "the machine has only two axes: nothing to draw here", "text-anchor=\"middle\"");
    return out + "</g>\n";
  }
  Range rh, rv;
  for (const auto& s : trace.strokes)
    for (const auto& q : s.points) {
      rh.add(q[v.h]);
      rv.add(q[v.v]);
    }
  const ViewScale s(rh, rv, p);
  out += axes_of(s, p, m, v);
  if (rh.empty) {
    out += text(p.left + p.size / 2, p.top + p.size / 2, "no motion", "text-anchor=\"middle\"");
    return out + "</g>\n";
  }
  for (const auto& stroke : trace.strokes) {
    std::string d;
    std::string last;
    for (const auto& q : stroke.points) {
      const std::string xy = px(s.x(q[v.h])) + " " + px(s.y(q[v.v]));
      if (xy == last) continue;
      d += (d.empty() ? "M" : " L") + xy;
      last = xy;
    }
    if (d.find('L') == std::string::npos) d += " L" + last;  // seen end-on: still a dot
    out += "<path " + stroke_style(stroke.kind) + " fill=\"none\" d=\"" + d + "\"/>\n";
  }
  for (const auto& t : trace.probe_targets)
    out += "<circle class=\"probe-target\" cx=\"" + px(s.x(t[v.h])) + "\" cy=\"" + px(s.y(t[v.v])) +
           "\" r=\"4\" fill=\"none\" stroke=\"" + kProbeColour + "\" stroke-width=\"1.5\"/>\n";
  out += text(p.left, p.top + p.size + 56, "box: " + box_text(m, v.h, rh) + ", " + box_text(m, v.v, rv),
              "class=\"bbox\"");
  return out + "</g>\n";
}

std::string legend() {
  std::string out = "<g id=\"legend\">\n";
  double x = kLeft;
  const double y = kLegendTop + 15;
  for (auto [kind, label] : {std::pair{MoveKind::Feed, "feed move"}, std::pair{MoveKind::Rapid, "rapid (traverse)"},
                             std::pair{MoveKind::Probe, "probing move"}}) {
    out += "<path " + stroke_style(kind) + " fill=\"none\" d=\"M" + px(x) + " " + px(y - 4) + " L" + px(x + 40) + " " +
           px(y - 4) + "\"/>\n";
    out += text(x + 48, y, label);
    x += 190;
  }
  out += "<circle cx=\"" + px(x + 20) + "\" cy=\"" + px(y - 4) + "\" r=\"4\" fill=\"none\" stroke=\"" + kProbeColour +
         "\" stroke-width=\"1.5\"/>\n";
  out += text(x + 48, y, "probe target");
  return out + "</g>\n";
}

}  // namespace

std::string svg_plot(const PathTrace& trace, const planner::Machine& machine, std::string_view title) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(kWidth) + "\" height=\"" + px(kHeight) +
         "\" viewBox=\"0 0 " + px(kWidth) + " " + px(kHeight) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  out += "<title>" + escaped(title) + "</title>\n";
  out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const auto views = plot_views(machine);
  for (std::size_t i = 0; i < views.size(); ++i) out += view_svg(trace, machine, views[i], static_cast<double>(i) * kViewWidth);
  out += legend();
  return out + "</svg>\n";
}

}  // namespace imess::messprog
