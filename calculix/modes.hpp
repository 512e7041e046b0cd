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
// A spinning ring (rotation.speed != 0; check_spin's refusals): spinning_brick_deck, the ring
// as C3D20R bricks written by the deck (no MPC: see below), and its three steps (the
// centrifugal equilibrium, the real modes of the tangent, *COMPLEX FREQUENCY, CORIOLIS in their
// basis). omega: the real parts ccx prints in rad/time, in the frame that turns with the ring
// (frame = "rotating"), ascending; the centroid line's displacement at the 2 elements stations
// as the mean of each station's brick nodes; the in-plane modes by the kinetic-energy rule
// above; shapes and waves by modal::travelling_mode on them (ccx's x(t) = Re(x e^{i omega t}));
// no rigid modes. Measured against the inextensible closed form (tests/calculix/
// calculix_spin_test.cpp, R/h = 250, a foundation, 80 elements): the k = 2 and 3 pairs within
// 9e-5, Bryan's factor within 1e-5.
// Why not ccx's expansion of the B32R beams, as at rest: its Coriolis split comes out 0.28 %
// (k = 1) to 0.45 % (k = 4) low on a ring on a foundation, with either tension, at any mesh
// and basis. The same free ring has the closed form's split to 3e-5 (k = 2), and springs of no
// stiffness (1e-6 N/m^2) bring the whole deficit back: a spring on a beam node makes ccx tie it
// to the expanded section by an MPC whose dependent term is a corner of the section
// (gen3dconnect). Bricks written by hand with the springs on their own nodes have the split to
// 4e-5; one *EQUATION per section tying two of their nodes (real frequencies unchanged to 6
// digits) cuts it by 7.4 %. The likely mechanism, read in mafillcorio.f (calculix/cae's copy of
// the source): it assembles the skew Coriolis matrix with the symmetric matrices' MPC rules,
// and its "regular DOF / MPC" branch swaps the two degrees of freedom when the dependent one
// comes first, so an entry goes in where its transpose (the opposite sign) belongs. Neither
// the centrifugal softening's mass (the same deficit with tension = "none") nor the bricks'
// rotary inertia (order (h/R)^2 = 1.6e-5) has a part in it.
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
/// deck with eigenvalues_for(spec, count) eigenvalues, or a spinning ring's spinning_deck
/// with as many real and complex modes.
Deck modes_deck(const ring::RingSpec& spec, const ring::CalculixOptions& options, int count,
                const std::string& title = "");

/// The `count` lowest in-plane elastic modes. Throws ring::InputError (a term the deck
/// cannot express, no ccx) or ring::NumericalError (ccx failed; its last lines). `title`
/// goes into the deck's heading.
ring::ModalResult compute_modes(const ring::RingSpec& spec, const ring::CalculixOptions& options, int count,
                                const Hooks& hooks = {}, const std::string& title = "");

}  // namespace calculix
