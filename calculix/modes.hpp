// The CalculiX column: the lowest in-plane modes of a ring, computed by ccx.
//
// Method: write the frequency deck (deck.hpp), run ccx (ccx.hpp), read the modes of the
// beam nodes (dat.hpp) and keep the in-plane ones. ccx's model is three-dimensional: with
// the out-of-plane displacement of every beam node held, what remains out of the plane
// are the section's twisting modes, whose beam nodes do not move in the plane. A mode is
// in-plane when the in-plane kinetic energy of its beam nodes, sum m_k (ux^2 + uy^2) with
// the node's share m_k = rho A 2 pi R / nodes of the ring's mass, is more than half of its
// unit modal mass (measured: > 0.99 for every in-plane mode of the paper's ring, < 1e-12
// for the twisting ones). The rigid modes the supports leave (3, 1 or 0) are the lowest
// and are counted apart. If fewer in-plane modes than asked come back, ccx runs again with
// twice the eigenvalues.
//
// Shapes: the beam nodes' displacements, linear between nodes (ring::sample_polygon), at
// the 360 common stations. Frequencies carry ccx's 7 printed digits.
//
// Cost: ccx's, about 18 s for 640 B32R elements and 30 eigenvalues on one thread
// (docs/measured.md); reading is O(nodes x modes).
#pragma once

#include "calculix/ccx.hpp"
#include "calculix/deck.hpp"
#include "ring/results.hpp"
#include "ring/spec.hpp"

namespace calculix {

/// The eigenvalues a deck asks of ccx for `count` in-plane elastic modes: rigid + count +
/// room for the twisting modes in between.
int eigenvalues_for(const ring::RingSpec& spec, int count);

/// The deck compute_modes runs first (`ringvib export-deck` writes it): the frequency
/// deck with eigenvalues_for(spec, count) eigenvalues.
Deck modes_deck(const ring::RingSpec& spec, const ring::CalculixOptions& options, int count,
                const std::string& title = "");

/// The `count` lowest in-plane elastic modes. Throws ring::InputError (a term the deck
/// cannot express, no ccx) or ring::NumericalError (ccx failed; its last lines). `title`
/// goes into the deck's heading.
ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::CalculixOptions& options, int count,
                                const Hooks& hooks = {}, const std::string& title = "");

}  // namespace calculix
