// VTU output of the linear ring's mode shapes (deal.II DataOut, ring_model.hpp).
#include "fem_reference/ring_model.hpp"

namespace fem::detail {
namespace {


/// For the VTU output: the Cartesian displacement of a mode from its two field
/// components (polar (u, w) on the circle, or already Cartesian on the polygon).
class CartesianDisplacement : public DataPostprocessorVector<2> {
 public:
  CartesianDisplacement(const std::string& name, bool polar)
      : DataPostprocessorVector<2>(name, update_values | update_quadrature_points), polar_(polar) {}
  void evaluate_vector_field(const DataPostprocessorInputs::Vector<2>& in,
                             std::vector<Vector<double>>& out) const override {
    for (unsigned int q = 0; q < in.solution_values.size(); ++q) {
      const double a0 = in.solution_values[q][0], a1 = in.solution_values[q][1];
      if (!polar_) {
        out[q][0] = a0;
        out[q][1] = a1;
        continue;
      }
      const double t = std::atan2(in.evaluation_points[q][1], in.evaluation_points[q][0]);
      out[q][0] = -std::sin(t) * a0 + std::cos(t) * a1;
      out[q][1] = std::cos(t) * a0 + std::sin(t) * a1;
    }
  }

 private:
  bool polar_;
};

}  // namespace

void RingModel::write_vtu(const std::vector<Vector<double>>& modes, const std::vector<double>& omega,
                          const std::string& file) const {
  write_ring_vtu(spec_, setup_, theta0_, cells_, modes, omega, file);
}

void write_ring_vtu(const ring::RingSpec& spec, const Setup& setup, double theta0,
                    const std::vector<DoFHandler<1>::active_cell_iterator>& cells_ccw,
                    const std::vector<Vector<double>>& modes, const std::vector<double>& omega,
                    const std::string& file) {
  // The same cells as a curve in the plane (Triangulation<1,2>, a closed loop), so that
  // ParaView shows the ring: the circle through a SphericalManifold, or the n-gon of
  // side 2 pi R / n. Local DoF orderings agree, so values are copied cell by cell.
  const bool curved = setup.geometry == Geometry::curved;
  const bool shear = setup.theory == ring::Theory::timoshenko;
  const unsigned int n = setup.cells(), m = setup.subdivisions;
  // An arch (ring.arc, curved geometry only: checks.cpp): n + 1 vertices, no closing cell.
  const bool open = spec.is_arch();
  const double h = spec.opening() / n;
  const double chord_angle = 2.0 * kPi / setup.elements;
  const double corner = curved ? spec.radius : spec.radius * (chord_angle / 2.0) / std::sin(chord_angle / 2.0);
  std::vector<Point<2>> vertices(open ? n + 1 : n);
  for (unsigned int i = 0; i < vertices.size(); ++i) {
    const double a0 = theta0 + (i / m) * chord_angle, a1 = a0 + chord_angle, f = double(i % m) / m;
    if (curved)
      vertices[i] = Point<2>(spec.radius * std::cos(theta0 + i * h), spec.radius * std::sin(theta0 + i * h));
    else
      vertices[i] = Point<2>(corner * ((1 - f) * std::cos(a0) + f * std::cos(a1)),
                             corner * ((1 - f) * std::sin(a0) + f * std::sin(a1)));
  }
  std::vector<CellData<1>> cells(n);
  for (unsigned int i = 0; i < n; ++i) cells[i].vertices = {i, open ? i + 1 : (i + 1) % n};
  Triangulation<1, 2> plane;
  plane.create_triangulation(vertices, cells, SubCellData());
  const SphericalManifold<1, 2> circle;
  if (curved) {
    plane.set_all_manifold_ids(0);
    plane.set_manifold(0, circle);
  }
  const FESystem<1, 2> fe(make_fe<2>(setup));
  DoFHandler<1, 2> dofs(plane);
  dofs.distribute_dofs(fe);

  DataOut<1, 2> data_out;
  data_out.attach_dof_handler(dofs);
  std::vector<Vector<double>> fields(modes.size(), Vector<double>(dofs.n_dofs()));
  std::vector<std::unique_ptr<CartesianDisplacement>> displacement;
  Vector<double> local(fe.n_dofs_per_cell());
  for (unsigned int k = 0; k < modes.size(); ++k) {
    // Scaled so that the largest nodal displacement is 1 (a Timoshenko rotation psi, in
    // rad, takes the same factor and is not counted).
    double largest = 0.0;
    for (const auto& cell : dofs.active_cell_iterators()) {
      cells_ccw[cell->index()]->get_dof_values(modes[k], local);
      cell->set_dof_values(local, fields[k]);
      for (unsigned int i = 0; i < local.size(); ++i)
        if (fe.system_to_component_index(i).first < 2) largest = std::max(largest, std::abs(local[i]));
    }
    if (largest > 0) fields[k] /= largest;
    std::ostringstream suffix;  // mode number and frequency (rad/s) in every name
    suffix << "_" << (k + 1) << "_omega_" << omega[k];
    // Timoshenko: the cross-section rotation psi as a third scalar.
    std::vector<std::string> names{(curved ? "tangential" : "ux") + suffix.str(), (curved ? "radial" : "uy") + suffix.str()};
    if (shear) names.push_back("rotation" + suffix.str());
    data_out.add_data_vector(fields[k], names);
    displacement.push_back(std::make_unique<CartesianDisplacement>("displacement" + suffix.str(), curved));
    data_out.add_data_vector(fields[k], *displacement.back());
  }
  const MappingQ<1, 2> mapping(std::max(2, setup.degree));
  data_out.build_patches(mapping, setup.degree + 1, DataOut<1, 2>::curved_inner_cells);
  std::ofstream out(file);
  if (!out) throw ring::NumericalError("fem: cannot write " + file);
  data_out.write_vtu(out);
  if (!out) throw ring::NumericalError("fem: writing " + file + " failed");
}

}  // namespace fem::detail

namespace fem {

using namespace detail;

std::string write_vtu(const ring::RingSpec& spec, const ring::FemOptions& options, int count,
                      const std::string& dir) {
  // The complex modes of a spinning ring (spin.hpp) have no full real fields to write yet.
  ring::refuse_rotation(spec, "fem: the VTU output of the modes");
  Solved s = run(spec, options, count, true);
  Setup setup;
  setup.elements = options.elements;
  setup.subdivisions = static_cast<int>(std::get<long long>(s.result.model.at("subdivisions")));
  setup.degree = static_cast<int>(std::get<long long>(s.result.model.at("degree")));
  setup.geometry = options.geometry;
  setup.rotary_inertia = options.rotary_inertia;
  setup.theory = spec.theory;
  setup.EA = spec.EA();
  const auto model = make_model(spec, setup);  // the same mesh and DoF numbering as the solve
  const std::string file = dir + "/fem_modes.vtu";
  model->write_vtu(s.full, s.result.omega, file);
  return file;
}

}  // namespace fem
