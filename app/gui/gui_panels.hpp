// The GUI's panels, each a function drawing one window's contents from the
// state (see gui_state.hpp for what they may change and what they request).
#pragma once

#include <imgui.h>

#include "gui_state.hpp"
#include "unfurl/render/plot.hpp"
#include "unfurl/render/trajectory_plots.hpp"

namespace unfurl::app {

// A width laid out for the 17 px font, at the current font's size: the
// panels scale with the UI scale.
inline float em(float pixels_at_17) { return pixels_at_17 * ImGui::GetFontSize() / 17.0f; }

// What the toolbar reports as wrong: the scene's error, a failed run.
std::string toolbar_error(const GuiState& state);

// Scene path, open, reload, the re-simulating indicator, and errors
// (wrapped to the window's width).
void toolbar_panel(GuiState& state, Requests& requests);

// The 3D view (a texture rendered beforehand at the size this panel asks
// for), camera by mouse: left drag orbits, right drag pans, wheel zooms.
void viewport_panel(GuiState& state, unsigned texture, const Eigen::AlignedBox3f& bounds);

// Scrubber with the computed span and latch marks, play/pause, speed,
// single steps, loop.
void timeline_panel(GuiState& state);

// Spring, latch, regulator and integrator settings built from the scene;
// undo, redo and saving the edited scene.
void parameters_panel(GuiState& state, Requests& requests);

// The workbench's plots: the scene's runs' (render::plot_kinds) and, for a
// scene with latches, the torque margin along the run.
std::vector<render::PlotKind> plot_kinds(const GuiState& state);
// The plots the selected tab shows, and where plot k of them goes in a
// panel of this size (one plot, or all in two columns).
std::vector<render::PlotKind> shown_plots(const GuiState& state);
ImVec4 plot_cell(std::size_t k, std::size_t count, ImVec2 panel);

// What the plots draw besides the current run: the previous run, the shown
// pinned runs, the chosen joints and the time zoom.
render::PlotChoice plot_choice(const GuiState& state);

// The plots (drawn beforehand into `texture` with the previous run as a
// ghost; `frames` says where each plot's axes are), the play-head over them,
// values on hover; a click seeks.
void plots_panel(GuiState& state, unsigned texture, const std::vector<render::PlotFrame>& frames);

// Save the frame, export a range as frames or video, save the trajectory.
void export_panel(GuiState& state, Requests& requests);

// A finished study: counts, histograms, the sortable table of cases; a
// click on a case asks to show it (study_panel.cpp).
void study_panel(GuiState& state, Requests& requests);

// Pin the current run, manage the pinned runs, and their difference table
// (runs_panel.cpp).
void runs_panel(GuiState& state, Requests& requests);

// The Modes tab: compute the deployed state's modes, list them, animate
// one in the view.
void modes_panel(GuiState& state, Requests& requests);

// Shows the file dialog for a path field, starting at the field's path.
void open_file_dialog(GuiState& state, FileField field);

// A "..." button after a path field: opens the file dialog for it.
void browse_button(GuiState& state, FileField field, const char* id);

// The file dialog, when shown; its choice goes into its field (and opening
// a scene is requested).
void file_dialog_panel(GuiState& state, Requests& requests);

// Simulated time, wall time, steps, RHS calls, real-time factor, integrator.
void status_bar(const GuiState& state);

}  // namespace unfurl::app
