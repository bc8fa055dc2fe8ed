#include "unfurl/render/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace unfurl::render {

namespace {

struct Theme {
  ImU32 background, frame, grid, text, muted, event, shade;
};

Theme theme(bool light) {
  if (light)
    return {IM_COL32(255, 255, 255, 255), IM_COL32(40, 40, 40, 255), IM_COL32(225, 225, 228, 255),
            IM_COL32(20, 20, 20, 255),    IM_COL32(90, 90, 90, 255), IM_COL32(200, 60, 60, 200),
            IM_COL32(240, 170, 40, 60)};
  return {IM_COL32(28, 30, 36, 255),    IM_COL32(170, 170, 175, 255), IM_COL32(55, 58, 66, 255),
          IM_COL32(230, 230, 230, 255), IM_COL32(160, 160, 165, 255), IM_COL32(240, 110, 110, 200),
          IM_COL32(240, 170, 40, 55)};
}

// A tick's label with the digits its step needs: neighbours differ even on
// a zoomed axis (7.382, 7.384, not 7.38, 7.38).
std::string tick_label(double v, bool log_axis, double step) {
  char buf[32];
  if (std::abs(v) < 1e-12 * std::max(1.0, step)) v = 0;  // no "-0"
  const int step_exponent = static_cast<int>(std::floor(std::log10(step > 0 ? step : 1) + 1e-9));
  if (log_axis)
    std::snprintf(buf, sizeof buf, "1e%d", static_cast<int>(std::lround(v)));
  else if (v == 0 || (std::abs(v) >= 1e-3 && std::abs(v) < 1e5))
    std::snprintf(buf, sizeof buf, "%.*f", std::clamp(-step_exponent, 0, 9), v);
  else
    std::snprintf(buf, sizeof buf, "%.*e",
                  std::clamp(static_cast<int>(std::floor(std::log10(std::abs(v)))) - step_exponent, 0, 6), v);
  return buf;
}

// A ghost's colour: its own when translucent (a pinned run's), else faint.
ImU32 ghost_color(ImU32 color) {
  return (color >> IM_COL32_A_SHIFT) < 0xFF ? color : (color & 0x00FFFFFF) | 0x60000000;
}

// A value as placed on its axis: log10 on a log axis.
double axis_value(double v, bool log_axis) {
  return log_axis ? std::log10(std::max(v, std::numeric_limits<double>::min())) : v;
}

// A point the axes can show: finite, and positive on a log axis.
bool plottable(double x, double y, bool log_x, bool log_y) {
  return std::isfinite(x) && std::isfinite(y) && !(log_x && x <= 0) && !(log_y && y <= 0);
}

void dashed_line(ImDrawList* draw, ImVec2 a, ImVec2 b, ImU32 color, float thickness, float dash) {
  const float dx = b.x - a.x, dy = b.y - a.y, length = std::sqrt(dx * dx + dy * dy);
  for (float s = 0; s < length; s += 2 * dash) {
    const float e = std::min(s + dash, length);
    draw->AddLine(ImVec2(a.x + dx * s / length, a.y + dy * s / length),
                  ImVec2(a.x + dx * e / length, a.y + dy * e / length), color, thickness);
  }
}

// A polyline drawn in dashes of `dash` pixels, the pattern running on
// across its vertices.
void dashed_polyline(ImDrawList* draw, const std::vector<ImVec2>& points, ImU32 color, float thickness, float dash) {
  float phase = 0;  // distance into the current dash-gap period
  for (std::size_t k = 1; k < points.size(); ++k) {
    const ImVec2 a = points[k - 1], b = points[k];
    const float dx = b.x - a.x, dy = b.y - a.y, length = std::sqrt(dx * dx + dy * dy);
    float s = 0;
    while (s < length) {
      const bool on = phase < dash;
      const float step = std::min(length - s, (on ? dash : 2 * dash) - phase);
      if (on)
        draw->AddLine(ImVec2(a.x + dx * s / length, a.y + dy * s / length),
                      ImVec2(a.x + dx * (s + step) / length, a.y + dy * (s + step) / length), color, thickness);
      s += step;
      phase = std::fmod(phase + step, 2 * dash);
    }
  }
}

// The series on screen, at most a minimum and a maximum per pixel column:
// long runs draw as fast as short ones and keep their peaks.
void screen_points(const PlotFrame& f, const Series& s, std::vector<ImVec2>& out) {
  out.clear();
  int column = std::numeric_limits<int>::min();
  ImVec2 first, last, top, bottom;  // of the samples in the current column
  std::size_t top_at = 0, bottom_at = 0;
  auto flush = [&] {
    if (column == std::numeric_limits<int>::min()) return;
    // Entry, extremes in time order, exit: the shape and the joins survive.
    out.push_back(first);
    if (top_at < bottom_at) {
      out.push_back(top);
      out.push_back(bottom);
    } else {
      out.push_back(bottom);
      out.push_back(top);
    }
    out.push_back(last);
  };
  for (std::size_t k = 0; k < s.x.size(); ++k) {
    if (!plottable(s.x[k], s.y[k], f.log_x, f.log_y)) continue;
    const ImVec2 p = f.to_screen(s.x[k], s.y[k]);
    const int c = static_cast<int>(std::floor(p.x));
    if (c != column) {
      flush();
      column = c;
      first = last = top = bottom = p;
      top_at = bottom_at = k;
      continue;
    }
    last = p;
    if (p.y < top.y) top = p, top_at = k;
    if (p.y > bottom.y) bottom = p, bottom_at = k;
  }
  flush();
  // Drop repeated points: they give the thick-line joins no direction.
  out.erase(std::unique(out.begin(), out.end(),
                        [](const ImVec2& a, const ImVec2& b) { return a.x == b.x && a.y == b.y; }),
            out.end());
}


// Which pixels of the axes hold some curve, at a 2 px resolution: what a
// legend box would hide, with curves drawn on top of each other counted once.
class Occupancy {
 public:
  explicit Occupancy(const PlotFrame& f)
      : origin_(f.plot_min),
        columns_(std::max(1, static_cast<int>((f.plot_max.x - f.plot_min.x) / cell) + 1)),
        rows_(std::max(1, static_cast<int>((f.plot_max.y - f.plot_min.y) / cell) + 1)),
        taken_(static_cast<std::size_t>(columns_) * rows_, 0) {}

  // Marks a polyline's pixels, sampled at most a cell apart.
  void mark(const std::vector<ImVec2>& polyline) {
    for (std::size_t k = 0; k < polyline.size(); ++k) {
      mark(polyline[k]);
      if (k == 0) continue;
      const ImVec2 a = polyline[k - 1], b = polyline[k];
      const int pieces = static_cast<int>(std::hypot(b.x - a.x, b.y - a.y) / cell);
      for (int i = 1; i < pieces; ++i) {
        const float t = static_cast<float>(i) / pieces;
        mark(ImVec2(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)));
      }
    }
  }

  int count(ImVec2 box_min, ImVec2 box_max) const {
    int n = 0;
    for (int r = row(box_min.y); r <= row(box_max.y); ++r)
      for (int c = column(box_min.x); c <= column(box_max.x); ++c) n += taken_[index(c, r)];
    return n;
  }

 private:
  static constexpr float cell = 2.0f;
  int column(float x) const { return std::clamp(static_cast<int>((x - origin_.x) / cell), 0, columns_ - 1); }
  int row(float y) const { return std::clamp(static_cast<int>((y - origin_.y) / cell), 0, rows_ - 1); }
  std::size_t index(int c, int r) const { return static_cast<std::size_t>(r) * columns_ + c; }
  void mark(ImVec2 p) {
    const float x = (p.x - origin_.x) / cell, y = (p.y - origin_.y) / cell;
    if (x >= 0 && y >= 0 && x < columns_ && y < rows_) taken_[index(static_cast<int>(x), static_cast<int>(y))] = 1;
  }

  ImVec2 origin_;
  int columns_, rows_;
  std::vector<char> taken_;
};

// The legend in the corner of the axes that hides the least of the curves
// (top right on a tie), with as many entries as fit.
void draw_legend(ImDrawList* draw, const PlotFrame& f, const PlotSpec& spec, const Theme& th,
                 const Occupancy& drawn) {
  const float font = ImGui::GetFontSize();
  struct Entry {
    std::string label;
    ImU32 color;
    bool dashed;
    bool dot = false;  // a scatter's series: a dot, not a line
    bool box = false;  // a shaded span
  };
  std::vector<Entry> entries, runs;
  for (const Series& s : spec.series) {
    if (!s.ghost) {
      entries.push_back({s.label, s.color, s.dashed, !s.lines});
      continue;
    }
    // One entry per other run; the unnamed ones (the previous run, the
    // other cases) share the spec's ghost label.
    const std::string label = s.run.empty() ? spec.ghost_label : s.run;
    if (label.empty() || std::any_of(runs.begin(), runs.end(), [&](const Entry& e) { return e.label == label; }))
      continue;
    const ImU32 color = ghost_color(s.color);
    runs.push_back({label, (color >> IM_COL32_A_SHIFT) < 0x90 ? (color & 0x00FFFFFF) | 0x90000000 : color, false,
                    !s.lines});
  }
  entries.insert(entries.end(), runs.begin(), runs.end());
  if (!spec.shaded.empty()) entries.push_back({spec.shaded_label, th.shade, false, false, true});
  if (!spec.events.empty()) entries.push_back({spec.event_label, th.event, true});
  if (entries.empty()) return;
  // As many entries as fit: in columns when a short plot has more curves
  // than rows, and "+N more" beyond that.
  const float line = 1.2f * font, swatch = 1.6f * font, margin = 0.5f * font;
  const int room = static_cast<int>((f.plot_max.y - f.plot_min.y - 1.5f * font) / line);
  if (room < 2) return;  // too small for a useful legend
  float widest = ImGui::CalcTextSize("+99 more").x;
  for (const auto& e : entries) widest = std::max(widest, ImGui::CalcTextSize(e.label.c_str()).x);
  const float column_width = widest + swatch + 1.5f * font;
  const int total = static_cast<int>(entries.size());
  const int most_columns = std::max(1, static_cast<int>(0.7f * (f.plot_max.x - f.plot_min.x) / column_width));
  const int columns = std::min(most_columns, (total + room - 1) / room);
  std::string more;
  if (total > room * columns) {
    const int kept = room * columns - 1;
    more = "+" + std::to_string(total - kept) + " more";
    // The event marker's entry stays: it explains the dashed verticals.
    const bool events_last = !spec.events.empty();
    const Entry events = entries.back();
    entries.resize(std::max(0, kept - (events_last ? 1 : 0)));
    if (events_last) entries.push_back(events);
  }
  const int slots = static_cast<int>(entries.size()) + (more.empty() ? 0 : 1);
  const int rows = std::min(room, (slots + columns - 1) / columns);
  const ImVec2 box(columns * column_width, rows * line + margin);
  ImVec2 box_min;
  int fewest = std::numeric_limits<int>::max();
  for (const bool top : {true, false})
    for (const bool right : {true, false}) {
      const ImVec2 corner(right ? f.plot_max.x - margin - box.x : f.plot_min.x + margin,
                          top ? f.plot_min.y + margin : f.plot_max.y - margin - box.y);
      const int hidden = drawn.count(corner, ImVec2(corner.x + box.x, corner.y + box.y));
      if (hidden < fewest) fewest = hidden, box_min = corner;
    }
  const ImVec2 box_max(box_min.x + box.x, box_min.y + box.y);
  draw->AddRectFilled(box_min, box_max, (th.background & 0x00FFFFFF) | 0xE0000000);
  draw->AddRect(box_min, box_max, th.grid);
  for (int k = 0; k < slots; ++k) {
    const float x = box_min.x + margin + static_cast<float>(k / rows) * column_width;
    const float y = box_min.y + margin + static_cast<float>(k % rows) * line;
    if (k == static_cast<int>(entries.size())) {
      draw->AddText(ImVec2(x, y + (line - font) / 2), th.muted, more.c_str());
      break;
    }
    const Entry& e = entries[k];
    const ImVec2 a(x, y + line / 2), b(a.x + swatch, a.y);
    if (e.box)
      draw->AddRectFilled(ImVec2(a.x, a.y - 0.35f * font), ImVec2(b.x, a.y + 0.35f * font), e.color | 0x60000000);
    else if (e.dot)
      draw->AddCircleFilled(ImVec2(0.5f * (a.x + b.x), a.y), 0.22f * font, e.color);
    else if (e.dashed)
      dashed_line(draw, a, b, e.color, e.color == th.event ? 1.5f : 2.5f, 4);
    else
      draw->AddLine(a, b, e.color, 2.5f);
    draw->AddText(ImVec2(b.x + margin, y + (line - font) / 2), th.text, e.label.c_str());
  }
}

}  // namespace

// Every hue reads on white (the PNGs) and on the GUI's dark background.
ImU32 palette(int i) {
  static const ImU32 colors[] = {IM_COL32(31, 119, 180, 255),  IM_COL32(255, 127, 14, 255),
                                 IM_COL32(44, 160, 44, 255),   IM_COL32(214, 39, 40, 255),
                                 IM_COL32(148, 103, 189, 255), IM_COL32(140, 86, 75, 255),
                                 IM_COL32(227, 119, 194, 255), IM_COL32(127, 127, 127, 255),
                                 IM_COL32(188, 189, 34, 255),  IM_COL32(23, 190, 207, 255),
                                 IM_COL32(110, 110, 255, 255), IM_COL32(190, 150, 0, 255)};
  return colors[i % 12];
}

std::vector<double> nice_ticks(double lo, double hi, int target_count) {
  std::vector<double> ticks;
  if (!(hi > lo)) return {lo};
  const double raw = (hi - lo) / std::max(1, target_count);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * magnitude >= raw) {
      step = m * magnitude;
      break;
    }
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step) ticks.push_back(t);
  return ticks;
}

std::vector<double> decade_ticks(double lo_exp, double hi_exp, int target_count) {
  std::vector<double> ticks;
  const int first = static_cast<int>(std::ceil(lo_exp - 1e-9)), last = static_cast<int>(std::floor(hi_exp + 1e-9));
  const int stride = std::max(1, (last - first + target_count - 1) / std::max(1, target_count));
  for (int e = first; e <= last; e += stride) ticks.push_back(e);
  return ticks;
}

ImVec2 PlotFrame::to_screen(double x, double y) const {
  const double fx = (axis_value(x, log_x) - x_min) / (x_max - x_min);
  const double fy = (axis_value(y, log_y) - y_min) / (y_max - y_min);
  return ImVec2(plot_min.x + static_cast<float>(fx) * (plot_max.x - plot_min.x),
                plot_max.y - static_cast<float>(fy) * (plot_max.y - plot_min.y));
}

double PlotFrame::x_at(float screen_x) const {
  const double x = x_min + (screen_x - plot_min.x) / (plot_max.x - plot_min.x) * (x_max - x_min);
  return log_x ? std::pow(10.0, x) : x;
}

PlotFrame draw_plot(ImDrawList* draw, ImVec2 origin, ImVec2 size, const PlotSpec& spec, bool light) {
  const Theme th = theme(light);
  const float font = ImGui::GetFontSize();
  PlotFrame f;
  f.log_x = spec.log_x;
  f.log_y = spec.log_y;
  // A short plot (one of several in a panel) keeps its axes tall: the
  // x-axis label moves to the end of the tick row.
  const bool compact = size.y < 11 * font;
  float left = 5.0f * font;
  for (const std::string& row : spec.y_categories) left = std::max(left, ImGui::CalcTextSize(row.c_str()).x + font);
  f.plot_min = ImVec2(origin.x + left, origin.y + (compact ? 1.5f : 2.2f) * font);
  f.plot_max = ImVec2(origin.x + size.x - 1.2f * font, origin.y + size.y - (compact ? 1.4f : 3.0f) * font);
  const ImVec2 corner(origin.x + size.x, origin.y + size.y);
  draw->PushClipRect(origin, corner, true);
  draw->AddRectFilled(origin, corner, th.background);

  // Data ranges: of everything, or of what lies in the zoomed span.
  const bool zoomed = spec.x_range && !spec.log_x && spec.x_range->second > spec.x_range->first;
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const Series& s : spec.series)
    for (std::size_t k = 0; k < s.x.size(); ++k) {
      if (!plottable(s.x[k], s.y[k], spec.log_x, spec.log_y)) continue;
      if (zoomed && (s.x[k] < spec.x_range->first || s.x[k] > spec.x_range->second)) continue;
      const double x = axis_value(s.x[k], spec.log_x), y = axis_value(s.y[k], spec.log_y);
      x0 = std::min(x0, x), x1 = std::max(x1, x);
      y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  if (!std::isfinite(x0)) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  if (zoomed) x0 = spec.x_range->first, x1 = spec.x_range->second;
  if (spec.log_x) {
    x0 = std::floor(x0), x1 = std::ceil(x1);
    if (x1 <= x0) x1 = x0 + 1;
  } else if (x1 <= x0) {
    x1 = x0 + 1;
  }
  if (!spec.y_categories.empty()) {
    // Reversed: row 0 at the top.
    y0 = static_cast<double>(spec.y_categories.size()) - 0.5, y1 = -0.5;
  } else if (spec.log_y) {
    y0 = std::floor(y0), y1 = std::ceil(y1);
    if (y1 <= y0) y1 = y0 + 1;
  } else {
    const double pad = y1 > y0 ? 0.05 * (y1 - y0) : std::max(1.0, std::abs(y0)) * 0.1;
    y0 -= pad, y1 += pad;
  }
  f.x_min = x0, f.x_max = x1, f.y_min = y0, f.y_max = y1;

  // Grid, ticks and labels.
  // As many ticks as the axes have room for.
  const int x_room = std::max(2, static_cast<int>((f.plot_max.x - f.plot_min.x) / (6 * font)));
  const int y_room = std::max(3, static_cast<int>((f.plot_max.y - f.plot_min.y) / (2.5f * font)));
  // A linear axis gets three labelled ticks where they fit, even when its
  // range sits just past a round step (-1.6 to 1.6 at a step of 2 has one),
  // and never more than its length has room for.
  const int y_fit = std::max(2, static_cast<int>((f.plot_max.y - f.plot_min.y) / (1.3f * font)) + 1);
  const auto linear_ticks = [](double lo, double hi, int target, int fit) {
    std::vector<double> ticks = nice_ticks(lo, hi, target);
    while (static_cast<int>(ticks.size()) < std::min(3, fit) && target < 12) ticks = nice_ticks(lo, hi, ++target);
    while (static_cast<int>(ticks.size()) > fit && target > 1) ticks = nice_ticks(lo, hi, --target);
    return ticks;
  };
  const std::vector<double> xt =
      spec.log_x ? decade_ticks(x0, x1, x_room) : linear_ticks(x0, x1, std::min(8, x_room), x_room + 1);
  std::vector<double> yt;
  if (spec.y_categories.empty())
    yt = spec.log_y ? decade_ticks(y0, y1, std::min(y_room, y_fit)) : linear_ticks(y0, y1, std::min(6, y_room), y_fit);
  const ImVec2 xs = ImGui::CalcTextSize(spec.x_label.c_str());
  const float x_label_left = compact ? f.plot_max.x - xs.x : corner.x;
  for (double x : xt) {
    const float sx = f.plot_min.x + static_cast<float>((x - x0) / (x1 - x0)) * (f.plot_max.x - f.plot_min.x);
    draw->AddLine(ImVec2(sx, f.plot_min.y), ImVec2(sx, f.plot_max.y), th.grid);
    const std::string label = tick_label(x, spec.log_x, xt.size() > 1 ? xt[1] - xt[0] : 1);
    const ImVec2 ts = ImGui::CalcTextSize(label.c_str());
    if (sx + ts.x / 2 + 0.5f * font > x_label_left) continue;
    draw->AddText(ImVec2(sx - ts.x / 2, f.plot_max.y + 0.2f * font), th.text, label.c_str());
  }
  for (std::size_t row = 0; row < spec.y_categories.size(); ++row) {
    const float sy =
        f.plot_max.y - static_cast<float>((static_cast<double>(row) - y0) / (y1 - y0)) * (f.plot_max.y - f.plot_min.y);
    draw->AddLine(ImVec2(f.plot_min.x, sy), ImVec2(f.plot_max.x, sy), th.grid);
    const ImVec2 ts = ImGui::CalcTextSize(spec.y_categories[row].c_str());
    draw->AddText(ImVec2(f.plot_min.x - ts.x - 0.4f * font, sy - ts.y / 2), th.text, spec.y_categories[row].c_str());
  }
  for (double y : yt) {
    const float sy = f.plot_max.y - static_cast<float>((y - y0) / (y1 - y0)) * (f.plot_max.y - f.plot_min.y);
    draw->AddLine(ImVec2(f.plot_min.x, sy), ImVec2(f.plot_max.x, sy), th.grid);
    const std::string label = tick_label(y, spec.log_y, yt.size() > 1 ? yt[1] - yt[0] : 1);
    const ImVec2 ts = ImGui::CalcTextSize(label.c_str());
    draw->AddText(ImVec2(f.plot_min.x - ts.x - 0.4f * font, sy - ts.y / 2), th.text, label.c_str());
  }
  // The title with the quantity's unit, over the axes; a short plot puts
  // the unit first, where a narrow cell does not clip it.
  const float title_y = origin.y + (compact ? 0.2f : 0.4f) * font;
  if (compact) {
    const ImVec2 unit_size = ImGui::CalcTextSize(spec.y_label.c_str());
    draw->AddText(ImVec2(origin.x + 0.4f * font, title_y), th.muted, spec.y_label.c_str());
    draw->AddText(ImVec2(origin.x + unit_size.x + 1.4f * font, title_y), th.text, spec.title.c_str());
  } else {
    // Over the axes, moved left as far as the picture's edge when a wide
    // margin (long category names) would push it past the right edge.
    const ImVec2 title_size = ImGui::CalcTextSize(spec.title.c_str());
    const float unit_width = spec.y_label.empty() ? 0.0f : font + ImGui::CalcTextSize(spec.y_label.c_str()).x;
    const float room = origin.x + size.x - 0.4f * font - title_size.x - unit_width;
    const float title_x = std::max(origin.x + 0.4f * font, std::min(f.plot_min.x, room));
    draw->AddText(ImVec2(title_x, title_y), th.text, spec.title.c_str());
    draw->AddText(ImVec2(title_x + title_size.x + font, title_y), th.muted, spec.y_label.c_str());
  }
  if (compact)
    draw->AddText(ImVec2(x_label_left, f.plot_max.y + 0.2f * font), th.muted, spec.x_label.c_str());
  else
    draw->AddText(ImVec2(std::max(origin.x + 0.4f * font,
                                  std::min((f.plot_min.x + f.plot_max.x - xs.x) / 2, origin.x + size.x - 0.4f * font - xs.x)),
                         f.plot_max.y + 1.6f * font),
                  th.muted, spec.x_label.c_str());

  // Curves, clipped to the axes.
  draw->PushClipRect(f.plot_min, f.plot_max, true);
  for (const auto& [a, b] : spec.shaded) {
    // At least two pixels: a single sample's span stays visible.
    const float sa = f.to_screen(a, spec.log_y ? 1 : y0).x, sb = f.to_screen(b, spec.log_y ? 1 : y0).x;
    draw->AddRectFilled(ImVec2(std::min(sa, sb - 2.0f), f.plot_min.y), ImVec2(sb, f.plot_max.y), th.shade);
  }
  for (const double e : spec.events) {
    const float sx = f.to_screen(e, spec.log_y ? 1 : y0).x;
    dashed_line(draw, ImVec2(sx, f.plot_min.y), ImVec2(sx, f.plot_max.y), th.event, 1.5f, 6);
  }
  std::vector<ImVec2> points;
  Occupancy drawn(f);
  for (int ghost = 1; ghost >= 0; --ghost)
    for (const Series& s : spec.series) {
      if (s.ghost != (ghost == 1)) continue;
      screen_points(f, s, points);
      drawn.mark(points);
      const ImU32 color = s.ghost ? ghost_color(s.color) : s.color;
      if (s.markers)
        for (std::size_t k = 0; k < s.x.size(); ++k)
          if (plottable(s.x[k], s.y[k], f.log_x, f.log_y)) draw->AddCircleFilled(f.to_screen(s.x[k], s.y[k]), 0.3f * font, color);
      if (!s.lines || points.size() < 2) continue;
      if (s.dashed)
        dashed_polyline(draw, points, color, s.ghost ? 1.5f : 2.0f, 0.5f * font);
      else
        draw->AddPolyline(points.data(), static_cast<int>(points.size()), color, ImDrawFlags_None, s.ghost ? 1.5f : 2.0f);
    }
  if (spec.cursor) {
    const float sx = f.to_screen(*spec.cursor, spec.log_y ? 1 : y0).x;
    draw->AddLine(ImVec2(sx, f.plot_min.y), ImVec2(sx, f.plot_max.y), th.text, 1.5f);
  }
  draw->PopClipRect();
  draw->AddRect(f.plot_min, f.plot_max, th.frame);

  draw_legend(draw, f, spec, th, drawn);
  draw->PopClipRect();
  return f;
}

}  // namespace unfurl::render
