// Figures made with gnuplot (run as a program). Each figure NAME is written as
// NAME.dat (the data), NAME.gp (the script, which a user can restyle and re-run with
// `gnuplot NAME.gp` in the same folder) and NAME.png (pngcairo), atomically.
#pragma once

#include <string>
#include <vector>

#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace cmp {

/// Writes NAME.dat and NAME.gp into `dir` and runs gnuplot to make NAME.png.
/// `script` is the plotting part; the terminal and output lines are added here.
/// Throws std::runtime_error if gnuplot fails (its stderr is in the message).
void render(const std::string& dir, const std::string& name, const std::string& script, const std::string& data,
            int width = 1200, int height = 900);

/// The first `count` (<= 9) mode shapes as in the paper's Figure 3: the deformed ring
/// over the undeformed one, one panel per mode, every model of `results` overlaid.
/// What a shape figure is called and how its panels are titled ("mode 3: 41.2 rad/s").
struct ShapeFigure {
  std::string name = "mode_shapes";        ///< NAME.png, NAME.gp, NAME.dat
  std::string title = "First mode shapes";
  std::string panel = "mode ";             ///< panel k's title: panel k: prefix value suffix
  std::string prefix, suffix = " rad/s";
};
void plot_mode_shapes(const std::string& dir, const std::vector<ring::ModalResult>& results, const ring::RingSpec& ring,
                      int count = 9, const ShapeFigure& figure = {});

/// Lines y[k] against x for several named series, with labelled axes (log-log if asked).
struct Series {
  std::string name;
  std::vector<double> x, y;
  static constexpr int kGrey = -2;
  int color = -1;       ///< palette index; -1: the series' position; kGrey: grey
  int dash = 1;         ///< gnuplot dash type: 1 solid, 2 dashed, 3 dotted, 4 dash-dotted
};
/// The undeformed centroid line (grey, dashed): the circle, or the arch of ring.arc, drawn
/// under the deformed rings of the shape figures.
Series undeformed_ring(const ring::RingSpec& ring);
/// A deformed centroid line through the nodes (x, y), m: closed back to its first node for a
/// ring, open for an arch.
Series deformed_line(std::string name, const std::vector<double>& x, const std::vector<double>& y,
                     const ring::RingSpec& ring, int color = -1, int dash = 1);

void plot_series(const std::string& dir, const std::string& name, const std::string& title, const std::string& xlabel,
                 const std::string& ylabel, const std::vector<Series>& series, bool logx = false, bool logy = false,
                 bool equal_aspect = false);

}  // namespace cmp
