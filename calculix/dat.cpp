#include "calculix/dat.hpp"

#include <cmath>
#include <sstream>

#include "ring/errors.hpp"

namespace calculix {
namespace {

/// Splits a line into whitespace-separated words.
std::vector<std::string> words(const std::string& line) {
  std::istringstream s(line);
  std::vector<std::string> w;
  for (std::string x; s >> x;) w.push_back(x);
  return w;
}

bool to_double(const std::string& s, double& x) {
  try {
    std::size_t used = 0;
    x = std::stod(s, &used);
    return used == s.size() && std::isfinite(x);
  } catch (...) {
    return false;
  }
}

bool to_int(const std::string& s, long& x) {
  try {
    std::size_t used = 0;
    x = std::stol(s, &used);
    return used == s.size();
  } catch (...) {
    return false;
  }
}

}  // namespace

std::vector<DatMode> read_frequency_dat(const std::string& text, int nodes, const std::string& name) {
  std::istringstream in(text);
  std::vector<DatMode> modes;
  auto fail = [&](int line, const std::string& what) {
    throw ring::NumericalError("calculix: " + name + ", line " + std::to_string(line) + ": " + what);
  };
  enum class State { start, table, between, block };
  State state = State::start;
  int line_no = 0, mode = -1, seen = 0;
  std::vector<bool> have;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (line.find("E I G E N V A L U E   O U T P U T") != std::string::npos) {
      if (!modes.empty()) fail(line_no, "a second eigenvalue table (one *FREQUENCY step expected)");
      state = State::table;
      continue;
    }
    if (line.find("E I G E N V A L U E    N U M B E R") != std::string::npos) {
      const auto w = words(line);
      long k = 0;
      if (w.empty() || !to_int(w.back(), k) || k < 1 || k > static_cast<long>(modes.size()))
        fail(line_no, "a mode number with no eigenvalue in the table");
      if (mode >= 0 && seen != nodes)
        fail(line_no, "mode " + std::to_string(mode + 1) + " has displacements of " + std::to_string(seen) + " of " +
                          std::to_string(nodes) + " nodes");
      mode = static_cast<int>(k - 1);
      modes[mode].ux.assign(nodes, 0.0);
      modes[mode].uy.assign(nodes, 0.0);
      modes[mode].uz.assign(nodes, 0.0);
      have.assign(nodes, false);
      seen = 0;
      state = State::block;
      continue;
    }
    const auto w = words(line);
    if (state == State::table) {
      if (line.find("P A R T I C I P A T I O N") != std::string::npos) {
        state = State::between;
        continue;
      }
      long k = 0;
      if (w.size() == 5 && to_int(w[0], k)) {
        double eig, omega, hz, imag;
        if (!to_double(w[1], eig) || !to_double(w[2], omega) || !to_double(w[3], hz) || !to_double(w[4], imag))
          fail(line_no, "expected: mode, eigenvalue, rad/time, cycles/time, imaginary part");
        if (k != static_cast<long>(modes.size()) + 1) fail(line_no, "modes out of order");
        DatMode m;
        m.omega = eig < 0.0 ? 0.0 : omega;  // a rigid mode's round-off may be a tiny negative eigenvalue
        modes.push_back(m);
      }
      continue;
    }
    if (state == State::block) {
      long node = 0;
      if (w.size() == 4 && to_int(w[0], node)) {
        double x, y, z;
        if (!to_double(w[1], x) || !to_double(w[2], y) || !to_double(w[3], z))
          fail(line_no, "expected: node, ux, uy, uz");
        if (node < 1 || node > nodes) fail(line_no, "node " + std::to_string(node) + " is not a beam node of the deck");
        if (have[node - 1]) fail(line_no, "node " + std::to_string(node) + " printed twice");
        have[node - 1] = true;
        ++seen;
        modes[mode].ux[node - 1] = x;
        modes[mode].uy[node - 1] = y;
        modes[mode].uz[node - 1] = z;
      }
    }
  }
  if (modes.empty()) fail(line_no, "no eigenvalue table (E I G E N V A L U E   O U T P U T)");
  if (mode >= 0 && seen != nodes)
    fail(line_no, "mode " + std::to_string(mode + 1) + " has displacements of " + std::to_string(seen) + " of " +
                      std::to_string(nodes) + " nodes");
  for (std::size_t k = 0; k < modes.size(); ++k)
    if (modes[k].ux.empty()) fail(line_no, "mode " + std::to_string(k + 1) + " has no displacements (NODE PRINT)");
  return modes;
}

std::vector<DatComplexMode> read_complex_dat(const std::string& text, int nodes, const std::string& name) {
  auto fail = [&](int line, const std::string& what) {
    throw ring::NumericalError("calculix: " + name + ", line " + std::to_string(line) + ": " + what);
  };
  std::vector<std::string> lines;
  {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
  }
  std::size_t table = lines.size();
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (lines[i].find("E I G E N V A L U E   O U T P U T") != std::string::npos) table = i;
  if (table == lines.size()) fail(static_cast<int>(lines.size()), "no eigenvalue table (E I G E N V A L U E   O U T P U T)");
  std::vector<DatComplexMode> modes;
  std::size_t i = table + 1;
  for (; i < lines.size(); ++i) {
    if (lines[i].find("P A R T I C I P A T I O N") != std::string::npos ||
        lines[i].find("E I G E N V A L U E    N U M B E R") != std::string::npos)
      break;
    const auto w = words(lines[i]);
    long k = 0;
    if (w.size() == 4 && to_int(w[0], k)) {
      double omega, hz, imag;
      if (!to_double(w[1], omega) || !to_double(w[2], hz) || !to_double(w[3], imag))
        fail(static_cast<int>(i + 1), "expected: mode, rad/time, cycles/time, imaginary part");
      if (k != static_cast<long>(modes.size()) + 1) fail(static_cast<int>(i + 1), "modes out of order");
      DatComplexMode m;
      m.omega = omega;
      m.imag = imag;
      modes.push_back(m);
    }
  }
  if (modes.empty()) fail(static_cast<int>(table + 1), "an empty complex eigenvalue table");
  enum class Part { none, real, imag };
  Part part = Part::none;
  int mode = -1, seen = 0;
  std::vector<bool> have;
  auto close = [&](int line) {
    if (part != Part::none && seen != nodes)
      fail(line, "mode " + std::to_string(mode + 1) + " has displacements of " + std::to_string(seen) + " of " +
                     std::to_string(nodes) + " nodes");
    part = Part::none;
  };
  for (; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    const int no = static_cast<int>(i + 1);
    if (line.find("E I G E N V A L U E    N U M B E R") != std::string::npos) {
      close(no);
      const auto w = words(line);
      long k = 0;
      if (w.empty() || !to_int(w.back(), k) || k < 1 || k > static_cast<long>(modes.size()))
        fail(no, "a mode number with no eigenvalue in the table");
      mode = static_cast<int>(k - 1);
      modes[mode].ux.assign(nodes, 0.0);
      modes[mode].uy.assign(nodes, 0.0);
      continue;
    }
    const bool real = line.find("R E A L   P A R T") != std::string::npos;
    if (real || line.find("I M A G I N A R Y   P A R T") != std::string::npos) {
      close(no);
      if (mode < 0) fail(no, "a displacement block before its mode number");
      part = real ? Part::real : Part::imag;
      have.assign(nodes, false);
      seen = 0;
      continue;
    }
    if (line.find("E I G E N M O D E   T U R N I N G") != std::string::npos) {
      close(no);
      break;
    }
    if (part == Part::none) continue;
    const auto w = words(line);
    long node = 0;
    if (w.size() == 4 && to_int(w[0], node)) {
      double x, y, z;
      if (!to_double(w[1], x) || !to_double(w[2], y) || !to_double(w[3], z)) fail(no, "expected: node, ux, uy, uz");
      if (node < 1 || node > nodes) fail(no, "node " + std::to_string(node) + " is not a beam node of the deck");
      if (have[node - 1]) fail(no, "node " + std::to_string(node) + " printed twice");
      have[node - 1] = true;
      ++seen;
      const std::complex<double> unit = part == Part::real ? 1.0 : std::complex<double>(0.0, 1.0);
      modes[mode].ux[node - 1] += unit * x;
      modes[mode].uy[node - 1] += unit * y;
    }
  }
  close(static_cast<int>(lines.size()));
  for (std::size_t k = 0; k < modes.size(); ++k)
    if (modes[k].ux.empty())
      fail(static_cast<int>(lines.size()), "mode " + std::to_string(k + 1) + " has no displacements (NODE PRINT)");
  return modes;
}

std::vector<double> read_real_eigenvalues(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  std::vector<double> eig;
  bool table = false;
  int line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (line.find("E I G E N V A L U E   O U T P U T") != std::string::npos) {
      if (table) break;  // the next table: the first one is read
      table = true;
      continue;
    }
    if (!table) continue;
    if (line.find("P A R T I C I P A T I O N") != std::string::npos ||
        line.find("E I G E N V A L U E    N U M B E R") != std::string::npos)
      break;
    const auto w = words(line);
    long k = 0;
    double x = 0.0;
    if (w.size() == 5 && to_int(w[0], k)) {
      if (!to_double(w[1], x))
        throw ring::NumericalError("calculix: " + name + ", line " + std::to_string(line_no) + ": expected an eigenvalue");
      eig.push_back(x);
    }
  }
  if (eig.empty())
    throw ring::NumericalError("calculix: " + name + ": no eigenvalue table of a *FREQUENCY step");
  return eig;
}

DatStatic read_static_dat(const std::string& text, int nodes, const std::string& name) {
  std::istringstream in(text);
  DatStatic out;
  auto fail = [&](int line, const std::string& what) {
    throw ring::NumericalError("calculix: " + name + ", line " + std::to_string(line) + ": " + what);
  };
  enum class Block { none, displacements, forces, total };
  int plate = 0;  // the plate of a total block
  Block block = Block::none;
  int line_no = 0, seen = 0;
  std::vector<bool> have;
  auto close = [&](int line) {
    if (block == Block::displacements && seen != nodes)
      fail(line, "displacements of " + std::to_string(seen) + " of " + std::to_string(nodes) + " nodes");
    if (block == Block::forces && seen != 1)
      fail(line, "a forces block of " + std::to_string(seen) + " nodes (one, the driven node, expected)");
    if (block == Block::total && seen != 1) fail(line, "a total force block without its row (fx, fy, fz)");
  };
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    const auto w = words(line);
    const bool displacements = line.find("displacements (vx,vy,vz)") != std::string::npos;
    if (displacements || line.find("forces (fx,fy,fz)") != std::string::npos) {
      close(line_no);
      double t = 0.0;
      if (w.empty() || !to_double(w.back(), t)) fail(line_no, "expected the time at the end of the line");
      if (displacements) {
        DatStatic::Increment inc;
        inc.time = t;
        inc.ux.assign(nodes, 0.0);
        inc.uy.assign(nodes, 0.0);
        out.all.push_back(std::move(inc));
        have.assign(nodes, false);
        block = Block::displacements;
      } else {
        if (out.all.empty() || out.all.back().time != t || !std::isnan(out.all.back().force[0]))
          fail(line_no, "a forces block without its increment's displacements before it");
        block = Block::forces;
      }
      seen = 0;
      continue;
    }
    if (line.find("total force (fx,fy,fz) for set NPLATE") != std::string::npos) {
      close(line_no);
      double t = 0.0;
      if (w.empty() || !to_double(w.back(), t)) fail(line_no, "expected the time at the end of the line");
      const std::size_t at = line.find("NPLATE") + 6;
      plate = at < line.size() && line[at] == '1' ? 1 : 0;
      if (out.all.empty() || out.all.back().time != t || !std::isnan(out.all.back().plates[plate][0]))
        fail(line_no, "a plate's total force without its increment's displacements before it");
      block = Block::total;
      seen = 0;
      continue;
    }
    if (block == Block::total && w.size() == 3) {
      double x, y, z;
      if (!to_double(w[0], x) || !to_double(w[1], y) || !to_double(w[2], z) || seen > 0)
        fail(line_no, "expected one row: fx, fy, fz");
      out.all.back().plates[plate] = {x, y};
      ++seen;
      continue;
    }
    long node = 0;
    if (block != Block::none && w.size() == 4 && to_int(w[0], node)) {
      double x, y, z;
      if (!to_double(w[1], x) || !to_double(w[2], y) || !to_double(w[3], z))
        fail(line_no, block == Block::forces ? "expected: node, fx, fy, fz" : "expected: node, ux, uy, uz");
      DatStatic::Increment& inc = out.all.back();
      if (block == Block::forces) {
        if (seen > 0) fail(line_no, "a forces block of more than one node (the driven node expected)");
        inc.force = {x, y};
        ++seen;
        continue;
      }
      if (node < 1 || node > nodes) fail(line_no, "node " + std::to_string(node) + " is not a beam node of the deck");
      if (have[node - 1]) fail(line_no, "node " + std::to_string(node) + " printed twice");
      have[node - 1] = true;
      ++seen;
      inc.ux[node - 1] = x;
      inc.uy[node - 1] = y;
    }
  }
  close(line_no);
  if (out.all.empty()) fail(line_no, "no displacements (NODE PRINT): no increment converged");
  out.increments = static_cast<int>(out.all.size());
  out.time = out.all.back().time;
  out.ux = out.all.back().ux;
  out.uy = out.all.back().uy;
  out.force = out.all.back().force;
  return out;
}

DatHistory read_history_dat(const std::string& text, const std::vector<int>& nodes, const std::string& name) {
  std::istringstream in(text);
  DatHistory out;
  out.ux.assign(nodes.size(), {});
  out.uy.assign(nodes.size(), {});
  auto fail = [&](int line, const std::string& what) {
    throw ring::NumericalError("calculix: " + name + ", line " + std::to_string(line) + ": " + what);
  };
  int line_no = 0;
  std::size_t seen = 0;
  bool block = false;
  auto close = [&](int line) {
    if (block && seen != nodes.size())
      fail(line, "displacements of " + std::to_string(seen) + " of the " + std::to_string(nodes.size()) +
                     " recorded nodes");
  };
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    const auto w = words(line);
    if (line.find("displacements (vx,vy,vz)") != std::string::npos) {
      close(line_no);
      double t = 0.0;
      if (w.empty() || !to_double(w.back(), t)) fail(line_no, "expected the time at the end of the line");
      out.t.push_back(t);
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        out.ux[i].push_back(NAN);
        out.uy[i].push_back(NAN);
      }
      seen = 0;
      block = true;
      continue;
    }
    long node = 0;
    if (block && w.size() == 4 && to_int(w[0], node)) {
      double x, y, z;
      if (!to_double(w[1], x) || !to_double(w[2], y) || !to_double(w[3], z)) fail(line_no, "expected: node, ux, uy, uz");
      bool found = false;
      for (std::size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i] == node) {
          if (!std::isnan(out.ux[i].back())) fail(line_no, "node " + std::to_string(node) + " printed twice");
          out.ux[i].back() = x;
          out.uy[i].back() = y;
          ++seen;
          found = true;
        }
      if (!found) fail(line_no, "node " + std::to_string(node) + " is not a recorded node");
    }
  }
  close(line_no);
  if (out.t.empty()) fail(line_no, "no displacements (NODE PRINT): no increment converged");
  return out;
}

long long equation_count(const std::string& log) {
  const auto at = log.find("number of equations");
  if (at == std::string::npos) return 0;
  std::istringstream s(log.substr(at + 19));
  long long n = 0;
  s >> n;
  return n;
}

}  // namespace calculix
