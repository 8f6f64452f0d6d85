// Contact between bodies on the grid with multiple velocity fields
// (Bardenhagen, Brackbill and Sulsky 2000; Nairn 2013): each body a case
// puts in contact maps its mass and momentum to a nodal field of its own,
// and a rigid body (its particles move with a prescribed velocity) maps
// only its volume. Where two fields meet at a node, the pair's contact law
// corrects their velocities (tasks/contact.hpp); the bodies in no contact
// share the grid's own field (field 0), as without contact.
// Fields are numbered: 0 the grid's, 1..K the deformable contact bodies',
// K+1..K+R the rigid bodies'. Present in a system only when its case has
// [[contacts]] (DiscreteSystem::contact).
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "discretisation/contact/contact_laws.hpp"
#include "discretisation/contact/interface_displacement.hpp"
#include "discretisation/contact/particle_spread.hpp"
#include "discretisation/grid/grid.hpp"
#include "discretisation/loads/external_loads.hpp"

namespace flowmpm {

// A pair of fields in contact, and what the contact did over the last step.
struct ContactPair {
  std::string name;         // "block~floor", the timeseries' columns contact.<name>.*
  int first = 1, second = 2;  // fields: first deformable, second deformable or rigid
  ContactLaw law;
  // The bodies touch at a node where their volumes there, sum_p N_Ip V_p
  // of each, fill at least this fraction of the node's volume (prod h).
  double touch_fraction = 0.6;
  // Over the last step, on the first body (N; N/m in 2D): the normal force
  // (>= 0 pressing; an interface in tension pulls, < 0) and the tangential
  // force's magnitude.
  double normal_force = 0.0, tangential_force = 0.0;
  // An interface's stored energy at the start of the last step (J; J/m in 2D).
  double interface_energy = 0.0;
};

// A rigid body: its velocity (per axis, absent = 0), the force the bodies
// in contact put on it in the last step (N; N/m in 2D) and the work it has
// done on them since t = 0 (J; J/m in 2D).
template <int D>
struct RigidMotion {
  std::string name;
  AxisFunctions velocity;
  Vec<D> force = Vec<D>::Zero();
  double work = 0.0;

  Vec<D> at(double t) const { return axis_values<D>(velocity, t); }
};

// The impulses a contact pass applied, summed over the nodes (tasks/contact.hpp).
template <int D>
struct ContactImpulses {
  std::vector<double> normal;         // per pair: sum of -dp_a . n (N s)
  std::vector<Vec<D>> tangential;     // per pair: sum of the tangential impulses on a (N s)
  std::vector<Vec<D>> rigid_impulse;  // per rigid body: the impulse it gave the bodies (N s)
  std::vector<double> rigid_work;     // per rigid body: dp . V (J)
  double work = 0.0;                  // the work of the impulses on the fields (J)

  ContactImpulses(std::size_t pairs, std::size_t rigid_bodies)
      : normal(pairs, 0.0),
        tangential(pairs, Vec<D>::Zero()),
        rigid_impulse(rigid_bodies, Vec<D>::Zero()),
        rigid_work(rigid_bodies, 0.0) {}

  ContactImpulses& operator+=(const ContactImpulses& o) {
    for (std::size_t i = 0; i < normal.size(); ++i) {
      normal[i] += o.normal[i];
      tangential[i] += o.tangential[i];
    }
    for (std::size_t r = 0; r < rigid_impulse.size(); ++r) {
      rigid_impulse[r] += o.rigid_impulse[r];
      rigid_work[r] += o.rigid_work[r];
    }
    work += o.work;
    return *this;
  }
  ContactImpulses& operator*=(double share) {
    for (double& x : normal) x *= share;
    for (Vec<D>& x : tangential) x *= share;
    for (Vec<D>& x : rigid_impulse) x *= share;
    for (double& x : rigid_work) x *= share;
    work *= share;
    return *this;
  }
};

template <int D>
struct ContactFields {
  using VectorField = typename NodalField<D>::VectorField;
  std::vector<NodalField<D>> deformable;  // field k (1..K) at deformable[k - 1]
  std::vector<RigidMotion<D>> rigid;      // field K + 1 + r at rigid[r]
  // Per contact field k >= 1 at [k - 1]: the nodal volume sum_p N_Ip V_p
  // (m^3; m^2 in 2D) and sum_p V_p grad N_Ip, which points out of the body
  // at its surface nodes (the normals).
  std::vector<std::vector<double>> volume;
  std::vector<VectorField> volume_gradient;
  // Per contact field k at [k - 1]: where its particles lie around each
  // node (particle_spread.hpp), for the normals; the variance below which a
  // direction is left out, (h / 10)^2 of the smallest cell.
  std::vector<ParticleSpread<D>> spread;
  double spread_floor = 0.0;
  // The largest angle (rad) between the gradient's normal and the
  // particles' separating direction at which the gradient's is kept:
  // measured on the incline at four surface offsets (docs/validation/contact.md).
  static constexpr double normal_tolerance = 0.7853981633974483;  // 45 degrees
  // The least volume of a rigid body at a node, as a fraction of the
  // node's volume, that puts it there: less is a rounding's (tasks/contact.hpp).
  static constexpr double least_volume = 1e-9;
  // The thinnest body in contact, in cells, whose contact is trusted, with
  // every shape function (app/log_model.cpp warns below it): a block on a
  // rigid incline slid within 2.3 % on a floor 3 cells thick and more at
  // every surface offset, and up to 42 % short on one 1 to 2 cells thick
  // (docs/guide/contact.md).
  static constexpr double min_body_cells = 3.0;
  // Per deformable field k at [k - 1], the sums of its nodal displacement
  // (interface_displacement.hpp); empty for a field no interface bonds.
  std::vector<InterfaceDisplacement<D>> displacement;
  std::vector<ContactPair> pairs;
  // contact_law[a * fields + b]: the index into pairs of fields a < b, -1
  // for stick (fields = 1 + K + R).
  std::vector<int> pair_of;
  int fields = 1;
  // What of the impulses of the last contact_projected pass reaches the
  // particles (tasks/contact.hpp); contact_updated counts it with its own.
  ContactImpulses<D> projected{0, 0};

  // Sums of no impulses, one per pair and rigid body.
  ContactImpulses<D> no_impulses() const { return ContactImpulses<D>(pairs.size(), rigid.size()); }

  int deformable_count() const { return static_cast<int>(deformable.size()); }
  bool is_rigid(int field) const { return field > deformable_count(); }
  int pair_index(int a, int b) const { return pair_of[static_cast<std::size_t>(a * fields + b)]; }

  // Whether any rigid body has volume at node n (the laws count them as one field).
  bool rigid_at(std::size_t n) const {
    for (std::size_t r = 0; r < rigid.size(); ++r)
      if (volume[deformable.size() + r][n] > 0.0) return true;
    return false;
  }

  // Clears contact field k's volume, its gradient and its particles'
  // spread at node n.
  void clear_node(std::size_t field, std::size_t n) {
    volume[field - 1][n] = 0.0;
    for (int d = 0; d < D; ++d) volume_gradient[field - 1][d][n] = 0.0;
    for (auto& s : spread[field - 1].sum) s[n] = 0.0;
  }

  Vec<D> gradient(int field, std::size_t n) const {
    Vec<D> g;
    for (int d = 0; d < D; ++d) g[d] = volume_gradient[field - 1][d][n];
    return g;
  }
  // The unit normal out of field a towards b at node n: a volume gradient,
  // where it points within `normal_tolerance` of the direction that
  // separates the two bodies' particles at the node (particle_spread.hpp);
  // else that direction. Which gradient: a rigid body's (exact); of two
  // deformable bodies, the one nearer the separating direction, of a body
  // with at least a tenth of the pair's volume at the node (where none
  // separates them, the one with more volume). The gradient is no
  // surface's where the node lies deep inside a body (it vanishes there,
  // or takes the sign of a particle row on a node plane), near a face the
  // other body does not touch (the end of a floor beside a block on it),
  // or at a body's corner resting on the other's face (it tilts by up to
  // 45 degrees into the slide): docs/theory/contact.md. False where
  // neither gives a direction.
  bool outward_normal(int a, int b, std::size_t n, Vec<D>& normal) const {
    Vec<D> apart;
    const bool separated =
        separating_normal(spread[a - 1], volume[a - 1][n], spread[b - 1], volume[b - 1][n], n, spread_floor, apart);
    Vec<D> g;
    if (is_rigid(b)) {
      g = -gradient(b, n);
    } else {
      const Vec<D> from_a = gradient(a, n), from_b = -gradient(b, n);
      if (separated) {
        // A body with a sliver of volume at the node has a full-size
        // gradient that is no surface's: it takes part from a tenth of the pair's volume.
        const double least = 0.1 * (volume[a - 1][n] + volume[b - 1][n]);
        const double cos_a = volume[a - 1][n] >= least ? cosine(from_a, apart) : -2.0;
        const double cos_b = volume[b - 1][n] >= least ? cosine(from_b, apart) : -2.0;
        g = cos_a >= cos_b ? from_a : from_b;
      } else
        g = volume[b - 1][n] > volume[a - 1][n] ? from_b : from_a;
    }
    if (separated && !(cosine(g, apart) >= std::cos(normal_tolerance))) g = apart;
    const double length = g.norm();
    if (!(length > 0.0)) return false;
    normal = g / length;
    return true;
  }

 private:
  // The cosine of the angle between v and the unit vector u; -2 for v = 0.
  static double cosine(const Vec<D>& v, const Vec<D>& u) {
    const double length = v.norm();
    return length > 0.0 ? v.dot(u) / length : -2.0;
  }
};

}  // namespace flowmpm
