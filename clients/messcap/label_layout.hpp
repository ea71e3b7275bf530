// Text labels for the report's pictures, placed so that none overlaps another or leaves the
// picture: each tries places around its anchor, nearest first, toward its preferred side.
#pragma once
#include <string>
#include <vector>

namespace imess::messcap {

struct LabelRect {
  double x = 0, y = 0, w = 0, h = 0;  // top-left corner and size, px (SVG: y grows downward)
  bool overlaps(const LabelRect& o) const { return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h; }
  bool inside(const LabelRect& area) const {
    return x >= area.x && y >= area.y && x + w <= area.x + area.w && y + h <= area.y + area.h;
  }
};

struct LabelRequest {
  std::string text;
  double anchor_x = 0, anchor_y = 0;  // the point it names
  double toward_x = 1, toward_y = -1;  // the side it prefers (any length; 0 0: up and right)
};

struct PlacedLabel {
  std::string text;
  LabelRect box;                // where its text lies
  double baseline_x = 0, baseline_y = 0;  // where an SVG <text> (start-anchored) is written
  double anchor_x = 0, anchor_y = 0;
  bool far = false;             // placed away from its anchor: draw a leader line
};

// A generous width for sans-serif text (wider than most fonts' glyphs), so that a label placed
// by this estimate does not overlap another however the browser draws it.
double label_text_width(const std::string& text, double font_size);

// Places every request in order within `area`, keeping clear of the labels placed before it
// and, where it can, of `obstacles` (the points); a label with no free place takes the one it
// overlaps least, inside the area.
std::vector<PlacedLabel> place_labels(const std::vector<LabelRequest>& requests, const LabelRect& area,
                                      const std::vector<LabelRect>& obstacles, double font_size);

}  // namespace imess::messcap
