// Line plots drawn with an ImDrawList: axes with nice ticks (linear or
// logarithmic), labels, a legend, vertical event markers and an optional
// play-head. The same code draws the PNG plots and the GUI's plots.
#pragma once

#include <imgui.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace unfurl::render {

struct Series {
  std::string label;
  std::vector<double> x, y;
  ImU32 color = IM_COL32(255, 255, 255, 255);
  bool ghost = false;  // another run, drawn faint (or in its own colour when that is translucent)
  std::string run;     // a ghost's run: one legend entry per run; empty: one for all (PlotSpec::ghost_label)
  bool dashed = false;  // a second quantity of the same thing (an angle beside a distance)
  bool markers = false;  // a dot at every point (a few measured points, not a signal)
  bool lines = true;     // false: the dots alone (a scatter plot)
};

struct PlotSpec {
  std::string title, x_label, y_label;
  std::vector<Series> series;
  bool log_x = false, log_y = false;
  std::vector<double> events;    // x of vertical markers (latches)
  std::string event_label = "latch";
  std::string ghost_label = "previous run";  // the legend's one entry for the ghost series
  // x spans shaded behind the curves (where the loads are indeterminate),
  // with one legend entry.
  std::vector<std::pair<double, double>> shaded;
  std::string shaded_label;
  std::optional<double> cursor;  // x of the play-head
  // The span of x shown (a zoom, linear axes); y then fits the data inside it.
  std::optional<std::pair<double, double>> x_range;
  // A y axis of named rows instead of numbers: row i at y = i, the first at
  // the top (a dot chart of cases).
  std::vector<std::string> y_categories;
};

// Where the data went on screen: for hit tests (hover values) and tests.
struct PlotFrame {
  ImVec2 plot_min, plot_max;  // the axes' box
  double x_min = 0, x_max = 1, y_min = 0, y_max = 1;  // log10 of the data on a log axis
  bool log_x = false, log_y = false;
  ImVec2 to_screen(double x, double y) const;
  double x_at(float screen_x) const;
};

// Draws the plot in [origin, origin + size]; `light` picks dark text on a
// light background (PNG) or light text on a dark one (GUI).
PlotFrame draw_plot(ImDrawList* draw, ImVec2 origin, ImVec2 size, const PlotSpec& spec, bool light);

// The i-th colour of a palette of distinguishable hues.
ImU32 palette(int i);

// Ticks from lo to hi at a 1-2-5 step (linear) or at decades (log).
std::vector<double> nice_ticks(double lo, double hi, int target_count);
std::vector<double> decade_ticks(double lo_exp, double hi_exp, int target_count);

}  // namespace unfurl::render
