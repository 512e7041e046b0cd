#include "compare/plot.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "compare/files.hpp"
#include "compare/output.hpp"
#include "compare/table.hpp"

namespace cmp {
namespace {

std::string gp_string(const std::string& s) {  // a gnuplot double-quoted string
  std::string o = "\"";
  for (char c : s) o += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return o + "\"";
}

const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};
constexpr int kPalette = 8;
constexpr const char* kGrey = "#9a9a9a";  ///< Series::kGrey: context (the undeformed ring), not data

}  // namespace

void render(const std::string& dir, const std::string& name, const std::string& script, const std::string& data,
            int width, int height) {
  write_file(dir + "/" + name + ".dat", data);
  std::ostringstream gp;
  gp << "# " << name << ": made by ringvib; re-run with `gnuplot " << name << ".gp` in this folder.\n"
     << "set terminal pngcairo size " << width << "," << height << " enhanced font 'DejaVu Sans,11'\n"
     << "set output '" << name << ".png'\n"
     << "datafile = '" << name << ".dat'\n"
     << script;
  write_file(dir + "/" + name + ".gp", gp.str());
  // The folder is a private stage (files.hpp): gnuplot writes the PNG in place. It is
  // our direct child, so that a signal handler can stop it (install_signal_cleanup).
  const std::string piped = gp.str(), to = dir + "/" + name + ".png";
  int in[2], out_pipe[2];
  if (pipe(in) != 0) throw std::runtime_error("cannot run gnuplot for " + name);
  if (pipe(out_pipe) != 0) {
    close(in[0]);
    close(in[1]);
    throw std::runtime_error("cannot run gnuplot for " + name);
  }
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(in[0], STDIN_FILENO);
    dup2(out_pipe[1], STDOUT_FILENO);
    dup2(out_pipe[1], STDERR_FILENO);
    for (int fd : {in[0], in[1], out_pipe[0], out_pipe[1]}) close(fd);
    if (chdir(dir.c_str()) != 0) _exit(126);
    execlp("gnuplot", "gnuplot", static_cast<char*>(nullptr));
    _exit(127);
  }
  close(in[0]);
  close(out_pipe[1]);
  if (pid < 0) {
    close(in[1]);
    close(out_pipe[0]);
    throw std::runtime_error("cannot run gnuplot for " + name);
  }
  register_child(pid);
  // The script is a few KiB (the data is in NAME.dat): it fits the pipe's buffer.
  for (std::size_t done = 0; done < piped.size();) {
    const ssize_t n = write(in[1], piped.data() + done, piped.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  close(in[1]);
  // gnuplot's messages, of which a failure shows the last: kept to their last 64 KiB
  // however much it prints (an external program's log is read from its tail).
  constexpr std::size_t kKeep = 64 << 10;
  std::string out;
  char buf[512];
  for (ssize_t n; (n = read(out_pipe[0], buf, sizeof buf)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    out.append(buf, static_cast<std::size_t>(n));
    if (out.size() > 2 * kKeep) out.erase(0, out.size() - kKeep);
  }
  if (out.size() > kKeep) out.erase(0, out.size() - kKeep);
  close(out_pipe[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  register_child(0);
  const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0 && access(to.c_str(), F_OK) == 0;
  if (!ok) {
    throw std::runtime_error("gnuplot failed to draw " + name + ".png: " + (out.empty() ? "no output" : out));
  }
}

Series undeformed_ring(const ring::RingSpec& spec) {
  Series line{"undeformed", {}, {}, Series::kGrey, 2};
  const double from = spec.arc ? spec.arc->from : 0.0, span = spec.arc ? spec.arc->span() : 360.0;
  for (int i = 0; i <= 360; ++i) {
    const double t = (from + span * i / 360.0) * M_PI / 180.0;
    line.x.push_back(spec.radius * std::cos(t));
    line.y.push_back(spec.radius * std::sin(t));
  }
  return line;
}

Series deformed_line(std::string name, const std::vector<double>& x, const std::vector<double>& y,
                     const ring::RingSpec& spec, int color, int dash) {
  Series s{std::move(name), x, y, color, dash};
  if (!spec.arc && !x.empty()) {
    s.x.push_back(x.front());
    s.y.push_back(y.front());
  }
  return s;
}

void plot_mode_shapes(const std::string& dir, const std::vector<ring::ModalResult>& results, const ring::RingSpec& spec,
                      int count, const ShapeFigure& figure) {
  const double radius = spec.radius;
  // The stations drawn, in order along the centroid line: every one around a ring (closed by
  // the first again), the arch's from its `from` end to its `to` end.
  std::vector<int> stations;
  if (spec.arc) {
    const int first = static_cast<int>(std::ceil(spec.arc->from - 1e-9));
    for (int deg = first; deg <= spec.arc->to + 1e-9; ++deg)
      stations.push_back(static_cast<int>(ring::wrap_degrees(deg)) % ring::kStations);
  } else {
    for (int i = 0; i <= ring::kStations; ++i) stations.push_back(i % ring::kStations);
  }
  int modes = count;
  for (const auto& r : results) modes = std::min<int>(modes, static_cast<int>(r.shapes.size()));
  if (modes <= 0) return;
  // Data blocks: index (mode * models + model), columns x y of the deformed ring (m),
  // closed by repeating the first station (a ring; an arch is open). Amplitude: 15 % of the radius.
  const double a = 0.15 * radius;
  std::ostringstream d;
  d.precision(8);
  // Overlaid models are paired with the base by MAC and turned to the base's sign, so
  // that the same mode is drawn the same way up whatever each solver's normalization.
  std::vector<std::vector<int>> pairing;
  for (const auto& r : results) pairing.push_back(pair_by_mac(results[0], r));
  for (int k = 0; k < modes; ++k)
    for (std::size_t m = 0; m < results.size(); ++m) {
      const auto& r = results[m];
      const int j = pairing[m][k] >= 0 ? pairing[m][k] : k;
      ring::ModeShape s = r.shapes[j];
      double dot = 0.0;
      for (int i = 0; i < ring::kStations; ++i)
        dot += s.radial[i] * results[0].shapes[k].radial[i] + s.tangential[i] * results[0].shapes[k].tangential[i];
      if (dot < 0)
        for (int i = 0; i < ring::kStations; ++i) {
          s.radial[i] = -s.radial[i];
          s.tangential[i] = -s.tangential[i];
        }
      d << "# mode " << k + 1 << " " << r.solver << "\n";
      for (const int j : stations) {
        const double t = ring::station_angle(j) * M_PI / 180.0;
        const double rr = radius + a * s.radial[j];
        d << rr * std::cos(t) - a * s.tangential[j] * std::sin(t) << " "
          << rr * std::sin(t) + a * s.tangential[j] * std::cos(t) << "\n";
      }
      d << "\n\n";
    }
  const int cols = modes <= 4 ? 2 : 3, rows = (modes + cols - 1) / cols;
  std::ostringstream g;
  g << "set multiplot layout " << rows << "," << cols
    << " title " << gp_string(figure.title + (spec.arc ? " (deformed arch over the undeformed one" : " (deformed ring over the undeformed circle") + ", amplitude 15 % of R)") << "\n"
    << "set size ratio -1\nunset key\nset xtics format ''\nset ytics format ''\nset parametric\n"
    << "set trange [" << (spec.arc ? spec.arc->from * M_PI / 180.0 : 0.0) << ":"
    << (spec.arc ? spec.arc->to * M_PI / 180.0 : 2.0 * M_PI) << "]\n"
    << "set xrange [" << -1.3 * radius << ":" << 1.3 * radius << "]\nset yrange [" << -1.3 * radius << ":"
    << 1.3 * radius << "]\n";
  for (int k = 0; k < modes; ++k) {
    g << "set title "
      << gp_string(figure.panel + std::to_string(k + 1) + ": " + figure.prefix + sig4(results[0].omega[k]) + figure.suffix)
      << "\n";
    if (k == 0) g << "set key bottom right font ',9'\n";
    g << "plot " << radius << "*cos(t), " << radius << "*sin(t) lc rgb '#aaaaaa' dt 2 notitle";
    for (std::size_t m = 0; m < results.size(); ++m)
      g << ", datafile index " << k * results.size() + m << " using 1:2 with lines lw " << (m == 0 ? 2.0 : 1.5)
        << " dt " << (m == 0 ? 1 : 2) << " lc rgb '" << kColors[m % kPalette] << "' title " << gp_string(results[m].solver);
    g << "\n";
    if (k == 0) g << "unset key\n";
  }
  g << "unset multiplot\n";
  render(dir, figure.name, g.str(), d.str(), 1200, 400 * rows);
}

void plot_series(const std::string& dir, const std::string& name, const std::string& title, const std::string& xlabel,
                 const std::string& ylabel, const std::vector<Series>& series, bool logx, bool logy,
                 bool equal_aspect) {
  std::ostringstream d, g;
  d.precision(12);
  for (const auto& s : series) {
    d << "# " << s.name << "\n";
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (std::isfinite(s.y[i]) && (!logy || s.y[i] > 0)) d << s.x[i] << " " << s.y[i] << "\n";
    d << "\n\n";
  }
  g << "set title " << gp_string(title) << "\nset xlabel " << gp_string(xlabel) << "\nset ylabel " << gp_string(ylabel)
    << "\nset grid\n";
  // Error curves fall from the top left: their top right corner is free for the key.
  g << (logy ? "set key top right opaque box\n" : "set key outside right\n");
  if (equal_aspect) g << "set size ratio -1\n";
  if (logx) g << "set logscale x\n";
  if (logy) g << "set logscale y\nset format y '10^{%L}'\n";
  g << "plot ";
  for (std::size_t i = 0; i < series.size(); ++i) {
    const Series& s = series[i];
    const bool dense = equal_aspect || s.x.size() > 60;  // markers only where they can be told apart
    g << (i ? ", " : "") << "datafile index " << i << " using 1:2 with "
      << (dense ? "lines lw 2" : "linespoints lw 2 pt 7 ps 0.8") << " dt " << s.dash << " lc rgb '"
      << (s.color == Series::kGrey ? kGrey : kColors[(s.color >= 0 ? s.color : static_cast<int>(i)) % kPalette])
      << "' title " << gp_string(s.name);
  }
  g << "\n";
  render(dir, name, g.str(), d.str(), 1100, 650);
}

}  // namespace cmp
