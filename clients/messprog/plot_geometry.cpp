// Views, scale and ticks of the plot.
#include "plot_geometry.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace imess::messprog {
namespace {

int index_of(const planner::Machine& m, char letter, int not1 = -1, int not2 = -1) {
  for (int i = 0; i < m.count; ++i)
    if (m.axes[i].letter == letter && i != not1 && i != not2) return i;
  return -1;
}

int first_other(const planner::Machine& m, int not1, int not2 = -1) {
  for (int i = 0; i < m.count; ++i)
    if (i != not1 && i != not2) return i;
  return -1;
}

ViewAxes view(const planner::Machine& m, int h, int v, const char* what) {
  const char hl = m.axes[h].letter;
  const char vl = v >= 0 ? m.axes[v].letter : '-';
  std::string id = "view-";
  id += static_cast<char>(std::tolower(static_cast<unsigned char>(hl)));
  id += v >= 0 ? static_cast<char>(std::tolower(static_cast<unsigned char>(vl))) : '0';
  std::string title = std::string(1, hl) + "-" + std::string(1, vl) + " (" + what + ")";
  return {h, v, id, title};
}

}  // namespace

std::vector<ViewAxes> plot_views(const planner::Machine& m) {
  int h = index_of(m, 'X');
  if (h < 0) h = 0;
  int v1 = index_of(m, 'Y', h);
  if (v1 < 0) v1 = first_other(m, h);
  int v2 = index_of(m, 'Z', h, v1);
  if (v2 < 0) v2 = first_other(m, h, v1);
  const bool xyz = m.axes[h].letter == 'X' && v1 >= 0 && m.axes[v1].letter == 'Y';
  std::vector<ViewAxes> views;
  views.push_back(view(m, h, v1, xyz ? "top" : "first two axes"));
  if (v2 >= 0) {
    const bool front = m.axes[h].letter == 'X' && m.axes[v2].letter == 'Z';
    const std::string against = std::string(1, m.axes[v2].letter) + " against " + std::string(1, m.axes[h].letter);
    views.push_back(view(m, h, v2, front ? "front" : against.c_str()));
  } else {
    views.push_back(view(m, h, -1, "no third axis"));
  }
  return views;
}

void Range::add(double x) {
  if (empty) lo = hi = x;
  lo = std::min(lo, x);
  hi = std::max(hi, x);
  empty = false;
}

ViewScale::ViewScale(const Range& h, const Range& v, const Panel& panel) : panel_(panel) {
  double w = h.empty ? 0 : h.hi - h.lo, t = v.empty ? 0 : v.hi - v.lo;
  hc_ = h.empty ? 0 : (h.lo + h.hi) / 2;
  vc_ = v.empty ? 0 : (v.lo + v.hi) / 2;
  double big = std::max(w, t);
  if (big < 1e-9) big = w = t = 10;
  const double pad = 0.05 * big;
  w = std::max(w, 1e-9) + 2 * pad;
  t = std::max(t, 1e-9) + 2 * pad;
  scale_ = std::min(panel.size / w, panel.size / t);
}

std::vector<double> ticks(double lo, double hi) {
  std::vector<double> out;
  if (!(hi > lo)) return out;
  const double raw = (hi - lo) / 7;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double step = decade;
  for (double f : {1.0, 2.0, 5.0, 10.0})
    if (f * decade >= raw) {
      step = f * decade;
      break;
    }
  for (double k = std::ceil(lo / step); k * step <= hi + 1e-9 * step; k += 1) out.push_back(k * step);
  return out;
}

int tick_decimals(const std::vector<double>& t) {
  if (t.size() < 2) return 0;
  const double step = t[1] - t[0];
  return std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
}

}  // namespace imess::messprog
