// Label placement for the HTML report's views: candidates round the anchor, nearest and on the
// preferred side first, the first that is free wins.
#include "label_layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace imess::messcap {

double label_text_width(const std::string& text, double font_size) {
  double em = 0;
  for (unsigned char c : text) {
    if (c >= 0x80 && (c & 0xC0) == 0x80) continue;  // a UTF-8 continuation byte: part of the glyph before
    em += (c == 'm' || c == 'w' || c == 'M' || c == 'W') ? 0.9 : (c >= 'A' && c <= 'Z') ? 0.72 : 0.6;
  }
  return em * font_size + 2;
}

std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& requests, const LabelRect& area,
                                      const std::vector<LabelRect>& obstacles, double font_size) {
  std::vector<PlacedLabel> placed;
  const double h = font_size * 1.25;
  for (const auto& r : requests) {
    const double w = label_text_width(r.text, font_size);
    double tx = r.toward_x, ty = r.toward_y;
    const double len = std::hypot(tx, ty);
    if (len < 1e-9) {
      tx = 1;
      ty = -1;
    }
    const double start = std::atan2(ty, tx);
    // Every place: a distance from the anchor, a direction (the preferred one first, then
    // turning away from it both ways), the box on that side of the anchor.
    struct Candidate {
      LabelRect box;
      double distance;
    };
    std::vector<Candidate> candidates;
    for (double dist : {5.0, 10.0, 16.0, 24.0, 34.0, 46.0, 60.0, 80.0, 105.0})
      for (int k = 0; k < 16; ++k) {
        const int step = (k + 1) / 2 * (k % 2 == 0 ? 1 : -1);  // 0, -1, 1, -2, 2 ...
        const double a = start + step * (M_PI / 8);
        const double cx = r.anchor_x + std::cos(a) * (dist + w / 2), cy = r.anchor_y + std::sin(a) * (dist + h / 2);
        candidates.push_back({{cx - w / 2, cy - h / 2, w, h}, dist});
      }
    auto clashes = [&](const LabelRect& b, bool with_obstacles) {
      double overlap = 0;
      auto add = [&](const LabelRect& o) {
        const double ox = std::min(b.x + b.w, o.x + o.w) - std::max(b.x, o.x);
        const double oy = std::min(b.y + b.h, o.y + o.h) - std::max(b.y, o.y);
        if (ox > 0 && oy > 0) overlap += ox * oy;
      };
      for (const auto& p : placed) add(p.box);
      if (with_obstacles)
        for (const auto& o : obstacles) add(o);
      return overlap;
    };
    const Candidate* chosen = nullptr;
    for (bool with_obstacles : {true, false}) {
      for (const auto& c : candidates)
        if (c.box.inside(area) && clashes(c.box, with_obstacles) == 0) {
          chosen = &c;
          break;
        }
      if (chosen) break;
    }
    Candidate fallback{};
    if (!chosen) {  // nothing free round the anchor: the free place nearest to it anywhere in the area
      double best = std::numeric_limits<double>::infinity();
      for (double y = area.y; y + h <= area.y + area.h; y += 3)
        for (double x = area.x; x + w <= area.x + area.w; x += 3) {
          const LabelRect b{x, y, w, h};
          const double d = std::hypot(x + w / 2 - r.anchor_x, y + h / 2 - r.anchor_y);
          if (d < best && clashes(b, false) == 0) {
            best = d;
            fallback = {b, d};
          }
        }
      if (best < std::numeric_limits<double>::infinity()) chosen = &fallback;
    }
    if (!chosen) {  // nowhere free at all: the least overlap, moved inside the area
      double best = std::numeric_limits<double>::infinity();
      for (const auto& c : candidates) {
        LabelRect b = c.box;
        b.x = std::clamp(b.x, area.x, area.x + area.w - b.w);
        b.y = std::clamp(b.y, area.y, area.y + area.h - b.h);
        const double o = clashes(b, false);
        if (o < best) {
          best = o;
          fallback = {b, c.distance};
        }
      }
      chosen = &fallback;
    }
    PlacedLabel p;
    p.text = r.text;
    p.box = chosen->box;
    p.baseline_x = p.box.x + 1;
    p.baseline_y = p.box.y + h - font_size * 0.3;
    p.anchor_x = r.anchor_x;
    p.anchor_y = r.anchor_y;
    p.far = chosen->distance > 12;
    placed.push_back(p);
  }
  return placed;
}

}  // namespace imess::messcap
