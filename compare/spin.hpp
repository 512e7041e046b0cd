// A spinning ring's results as the driver reports them (issue 49). The solvers return the
// gyroscopic modes in the frame that turns with the ring, each with its wave (number k,
// forward or backward against the spin: ring::Wave); here they become
//  - the wave pairs: per k the lowest forward and backward mode, their frequencies in both
//    frames and Bryan's factor 1 - (w_b - w_f)/(2 k |speed|), the rate at which the pair's
//    standing pattern turns in space over the spin's (a gyroscope's scale factor);
//  - the fixed frame's frequencies when the scene asks (modes.frame = "fixed"): a wave k
//    travelling at w/k against the ring turns at w/k +- |speed| in space, so its frequency
//    there is |w + direction k |speed||, the direction in space flipping where it passes zero
//    (the critical speed, where a backward wave stands still).
// Cost: O(modes) per result.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "ring/results.hpp"

namespace cmp {

/// The wave pairs of a result in the turning frame (its waves), by ascending k; a k with no
/// forward or no backward mode among the result's modes has none.
std::vector<ring::SpinPair> spin_pairs(const ring::ModalResult& turning, double speed);

/// The turning frame's result in the fixed frame (file comment): omega, waves and shapes
/// re-sorted by the fixed frame's omega; a standing wave keeps its omega. frame = "fixed".
void to_fixed_frame(ring::ModalResult& r, double speed);

/// A solver's spinning result finished as the scene asks: spin_pairs filled, then the frame
/// converted when `fixed`. A result without waves (a column that reports no directions)
/// keeps its turning frame and gets no pairs; asked for the fixed frame it is a
/// std::invalid_argument naming modes.frame.
void finish_spin(ring::ModalResult& r, double speed, bool fixed);

/// "forward", "backward" or "standing".
const char* direction_name(int direction);

/// [{"wave", "forward", "backward", "forward_fixed", "backward_fixed", "bryan"}] (rad/s).
nlohmann::json spin_pairs_json(const std::vector<ring::SpinPair>& pairs);

/// A text section of the wave pairs (a line per solver and pair), or "" when none has any.
std::string spin_pairs_text(const std::vector<std::pair<std::string, std::vector<ring::SpinPair>>>& pairs,
                            bool markdown);

}  // namespace cmp
