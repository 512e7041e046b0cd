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

DatStatic read_static_dat(const std::string& text, int nodes, const std::string& name) {
  std::istringstream in(text);
  DatStatic out;
  auto fail = [&](int line, const std::string& what) {
    throw ring::NumericalError("calculix: " + name + ", line " + std::to_string(line) + ": " + what);
  };
  int line_no = 0, seen = 0;
  bool block = false;
  std::vector<bool> have;
  auto close = [&](int line) {
    if (block && seen != nodes)
      fail(line, "displacements of " + std::to_string(seen) + " of " + std::to_string(nodes) + " nodes");
  };
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    const auto w = words(line);
    if (line.find("displacements (vx,vy,vz)") != std::string::npos) {
      close(line_no);
      double t = 0.0;
      if (w.empty() || !to_double(w.back(), t)) fail(line_no, "expected the time at the end of the line");
      out.time = t;
      ++out.increments;
      out.ux.assign(nodes, 0.0);
      out.uy.assign(nodes, 0.0);
      have.assign(nodes, false);
      seen = 0;
      block = true;
      continue;
    }
    long node = 0;
    if (block && w.size() == 4 && to_int(w[0], node)) {
      double x, y, z;
      if (!to_double(w[1], x) || !to_double(w[2], y) || !to_double(w[3], z)) fail(line_no, "expected: node, ux, uy, uz");
      if (node < 1 || node > nodes) fail(line_no, "node " + std::to_string(node) + " is not a beam node of the deck");
      if (have[node - 1]) fail(line_no, "node " + std::to_string(node) + " printed twice");
      have[node - 1] = true;
      ++seen;
      out.ux[node - 1] = x;
      out.uy[node - 1] = y;
    }
  }
  close(line_no);
  if (out.increments == 0) fail(line_no, "no displacements (NODE PRINT): no increment converged");
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
