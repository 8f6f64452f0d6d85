// Two strands bonded over an overlap L by an imperfect interface of
// tangential stiffness D_t (the case's `interface` contact), one held at its
// free end, the other pulled along x at its free end; 2D plane stress, the
// strands kept from bending (a node set holds y over both), as the
// shear-lag model assumes. Closed form: Volkersen's shear-lag lap joint
// ([Volkersen 1938]; [da Silva 2009]) with the adhesive layer's
// G_a / t_a replaced by the interface stiffness, and the strands' own
// shear compliance added to it ([Tsai 1998]: the shear stress falls
// linearly from the interface to the strand's free face, so the interface
// moves t / (3 G) tau past the strand's mean displacement):
//   1 / D = 1 / D_t + t_1 / (3 G_1) + t_2 / (3 G_2),
//   alpha_i = 1 / (Q_i t_i),  lambda^2 = D (alpha_1 + alpha_2),
//   delta / P = alpha_1 a_1 + alpha_2 a_2
//             + [ (2 alpha_1 alpha_2 + (alpha_1^2 + alpha_2^2) cosh lambda L) / (lambda sinh lambda L)
//                 + alpha_1 alpha_2 L ] / (alpha_1 + alpha_2),
// P the load per unit width (N/m), delta the pulled end's displacement
// relative to the held end, a_i strand i's free length outside the
// overlap, t_i the thicknesses (along y),
// Q_i = E_x / (1 - nu_xy nu_yx) the axial stiffness of a strand held in y
// in plane stress and G_i = G_xy (orthotropic with its axes unturned, or
// linear elastic). The limits: a perfect bond (lambda -> inf) gives the
// overlap's L / (Q_1 t_1 + Q_2 t_2); D -> 0 gives 1 / (D L).
// P is the mean of the pull on the pulled end and the hold's reaction
// (their difference is the strands' inertia), delta the integral of the
// two node sets' prescribed velocities along x. Error, at the last sample:
// slope = |P / delta - K| / K, K = 1 / (delta / P). Measures: slope (P / delta,
// N/m^2), expected (K), load (P, N/m) and slip (delta, m).
#pragma once
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "materials/material.hpp"
#include "materials/orthotropic.hpp"
#include "verification/reference_context.hpp"

namespace flowmpm {

struct LapShear {
  static constexpr const char* type_name = "lap_shear";
  std::string held, pulled;              // the node sets
  TimeFunction held_velocity, pulled_velocity;  // along x (m/s)
  double expected = 0.0;                 // K (N/m^2)
  double load = 0.0, slip = 0.0;         // at the last sample

  // The axial stiffness Q and the shear modulus G of a strand in plane
  // stress held in y.
  struct Strand {
    double Q = 0.0, G = 0.0;
  };
  static Strand strand(ParameterTable& t, const SystemSpec& s, const BodySpec& body) {
    const Material& m = s.materials.at(static_cast<std::size_t>(body.material)).model;
    if (const auto* o = std::get_if<Orthotropic>(&m)) {
      t.require(body.material_axes == Vec3{} && !body.material_axes_center, "type",
                "strands whose orthotropic axes are the global ones for lap_shear (\"" + body.name + "\")");
      const auto& p = o->parameters;
      return {p.Ex / (1.0 - p.nuxy * p.nuxy * p.Ey / p.Ex), p.Gxy};
    }
    if (const auto* e = std::get_if<LinearElastic>(&m)) {
      const double E = e->parameters.youngs_modulus, nu = e->parameters.poisson_ratio;
      return {E / (1.0 - nu * nu), E / (2.0 * (1.0 + nu))};
    }
    t.fail("type", "strands of orthotropic or linear_elastic material for lap_shear (\"" + body.name + "\")");
  }

  // The node set `key` names: a plane x = at with a velocity along x.
  static const NodeSetSpec& end_set(ParameterTable& t, const SystemSpec& s, const char* key) {
    std::vector<std::string> names;
    for (const NodeSetSpec& n : s.node_sets) names.push_back(n.name);
    const std::string name = t.choice(key, names);
    const NodeSetSpec& set = *std::ranges::find(s.node_sets, name, &NodeSetSpec::name);
    t.require(set.is_plane && set.axis == 0 && set.velocity[0].has_value(), key,
              "a node set on a plane x = at with a velocity along x");
    return set;
  }

  static LapShear read(ParameterTable& t, const ReferenceContext& context) {
    const SystemSpec& s = context.system;
    LapShear r;
    t.require(s.dimension == 2 && s.plane_stress, "type", "a 2D plane stress case for lap_shear");
    const auto contact =
        std::ranges::find_if(s.contacts, [](const ContactSpec& c) { return is_interface(c.law); });
    t.require(contact != s.contacts.end(), "type", "a case with an interface contact between the strands for lap_shear");
    const double Dt = std::get<InterfaceLaw>(contact->law).tangential_stiffness;
    t.require(Dt > 0.0, "type", "an interface with tangential_stiffness > 0 for lap_shear");
    const BodySpec* bodies[2] = {&s.bodies.at(static_cast<std::size_t>(contact->first)),
                                 &s.bodies.at(static_cast<std::size_t>(contact->second))};
    const NodeSetSpec& held = end_set(t, s, "held");
    const NodeSetSpec& pulled = end_set(t, s, "pulled");
    r.held = held.name;
    r.pulled = pulled.name;
    r.held_velocity = *held.velocity[0];
    r.pulled_velocity = *pulled.velocity[0];
    // The strands: their boxes, the overlap along x, and which end each reaches.
    const BoxShape box[2] = {bodies[0]->shape.bounds(), bodies[1]->shape.bounds()};
    const double from = std::max(box[0].min[0], box[1].min[0]), to = std::min(box[0].max[0], box[1].max[0]);
    t.require(to > from, "type", "strands that overlap along x for lap_shear");
    const double L = to - from;
    double alpha[2], shear = 1.0 / Dt, free_length[2] = {0.0, 0.0};
    for (int i = 0; i < 2; ++i) {
      const double thickness = box[i].max[1] - box[i].min[1];
      const Strand m = strand(t, s, *bodies[i]);
      alpha[i] = 1.0 / (m.Q * thickness);
      shear += thickness / (3.0 * m.G);
      // Held or pulled: the end set at the strand's far end from the overlap.
      const double end = box[i].min[0] < from ? box[i].min[0] : box[i].max[0];
      free_length[i] = std::max(from - box[i].min[0], box[i].max[0] - to);
      t.require(std::abs(end - held.at) < 1e-9 * L || std::abs(end - pulled.at) < 1e-9 * L, "held",
                "node sets at the strands' free ends for lap_shear (\"" + bodies[i]->name + "\" ends at x = " +
                    std::to_string(end) + " m)");
    }
    // No bending: a node set holding y over both strands.
    const bool unbent = std::ranges::any_of(s.node_sets, [&](const NodeSetSpec& n) {
      if (n.is_plane || !n.velocity[1] || n.velocity[1]->points.size() != 1 || n.velocity[1]->points[0].second != 0.0)
        return false;
      for (const BoxShape& b : box)
        for (int d = 0; d < 2; ++d)
          if (n.box_min[d] > b.min[d] || n.box_max[d] < b.max[d]) return false;
      return true;
    });
    t.require(unbent, "type", "a node set holding y (velocity y = 0) over both strands for lap_shear (no bending)");
    const double a1 = alpha[0], a2 = alpha[1];
    const double lambda = std::sqrt((a1 + a2) / shear), x = lambda * L;
    const double overlap = ((2.0 * a1 * a2 + (a1 * a1 + a2 * a2) * std::cosh(x)) / (lambda * std::sinh(x)) + a1 * a2 * L) /
                           (a1 + a2);
    r.expected = 1.0 / (a1 * free_length[0] + a2 * free_length[1] + overlap);
    return r;
  }

  template <int D, class Shape>
  void initialise(DiscreteSystem<D, Shape>&) const {}

  // The integral of f from 0 to t (m).
  static double integral(const TimeFunction& f, double t) {
    double sum = 0.0, t0 = 0.0;
    const auto add = [&](double t1) {
      if (t1 > t0) sum += 0.5 * (f(t0) + f(t1)) * (t1 - t0), t0 = t1;
    };
    for (const auto& [tk, value] : f.points) add(std::min(tk, t));
    add(t);
    return sum;
  }

  template <int D, class Shape>
  void sample(const DiscreteSystem<D, Shape>& system) {
    double pull = 0.0, hold = 0.0;
    for (const NodeConstraint& c : system.constraints) {
      if (c.axis != 0) continue;
      if (c.name == pulled) pull = c.reaction;
      if (c.name == held) hold = c.reaction;
    }
    load = 0.5 * (pull - hold);
    slip = integral(pulled_velocity, system.t) - integral(held_velocity, system.t);
  }

  template <class F>
  void visit_state(F&& f) {
    f("load", load);
    f("slip", slip);
  }

  double slope() const { return slip != 0.0 ? load / slip : 0.0; }
  std::map<std::string, double> errors() const { return {{"slope", std::abs(slope() - expected) / expected}}; }
  std::map<std::string, double> measures() const {
    return {{"slope", slope()}, {"expected", expected}, {"load", load}, {"slip", slip}};
  }
};

}  // namespace flowmpm
