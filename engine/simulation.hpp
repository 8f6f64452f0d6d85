// A running simulation of one case: the Model, the step graph wired for the
// case's scheme, and what the time loop and the writers read off it.
#pragma once
#include <algorithm>
#include <functional>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string>

#include "engine/build_model.hpp"
#include "engine/diagnostics.hpp"
#include "engine/step_graph.hpp"
#include "io/snapshot.hpp"
#include "tasks/g2p.hpp"
#include "tasks/grid_update.hpp"
#include "tasks/p2g.hpp"

namespace flowmpm {

// The solution went wrong (a particle left the grid, a non-finite value).
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

template <int D, class Shape>
class Simulation {
 public:
  // `observer`, if given, is called as each stage starts (from any thread;
  // for the stages of one node, in their order, as the node starts).
  explicit Simulation(const Case& c, std::function<void(Stage)> observer = {})
      : fixed_dt_(c.dt_auto ? 0.0 : c.dt),
        observer_(std::move(observer)),
        graph_(wiring_of(c.scheme), [this](const StageGroup& stages) { run_node(stages); }) {
    build_model(c, model_);
  }

  // One step through the flow graph (or serially, as the reference).
  void advance() { finish_step([this] { graph_.run(); }); }
  void advance_serial() { finish_step([this] { graph_.run_serial(); }); }

  Model<D, Shape>& model() { return model_; }
  const Model<D, Shape>& model() const { return model_; }
  const StepGraph& graph() const { return graph_; }

  ParticleSnapshot snapshot() const {
    ParticleSnapshot s;
    snapshot_into(s);
    return s;
  }

  // Fills `s`, reusing its storage.
  void snapshot_into(ParticleSnapshot& s) const {
    s.position.clear();
    s.velocity.clear();
    s.stress.clear();
    s.strain.clear();
    s.volume.clear();
    s.mass.clear();
    s.material.clear();
    s.step = model_.step;
    s.time = model_.t;
    s.count = model_.particle_count();
    for (const auto& b : model_.batches) {
      for (std::size_t p = 0; p < b.size(); ++p) {
        for (int d = 0; d < 3; ++d) {
          s.position.push_back(d < D ? b.x[p][d] : 0.0);
          s.velocity.push_back(d < D ? b.v[p][d] : 0.0);
        }
        s.stress.insert(s.stress.end(), b.stress[p].begin(), b.stress[p].end());
        s.strain.insert(s.strain.end(), b.strain[p].begin(), b.strain[p].end());
        s.volume.push_back(b.volume[p]);
        s.mass.push_back(b.mass[p]);
        s.material.push_back(b.material);
      }
    }
  }

  // Sets the model's largest particle speed (it is measured during each
  // step; this measures it outside one, e.g. at the start).
  void measure_speed() {
    model_.max_speed_sq = 0.0;
    for (const auto& b : model_.batches)
      for (const auto& v : b.v) model_.max_speed_sq = std::max(model_.max_speed_sq, v.squaredNorm());
  }

  // Where the fastest particle is and how fast it moves, for messages.
  std::string fastest_particle() const {
    double best = -1.0;
    Vec<D> x = Vec<D>::Zero();
    for (const auto& b : model_.batches) {
      for (std::size_t p = 0; p < b.size(); ++p) {
        if (!(b.v[p].squaredNorm() <= best)) best = b.v[p].squaredNorm(), x = b.x[p];
      }
    }
    std::ostringstream s;
    s.precision(6);
    s << "a particle at " << position_text<D>(x) << " moves at " << std::sqrt(best) << " m/s";
    return s.str();
  }

  // Energies and volume-weighted mean stress and strain per body.
  TimeseriesRow diagnostics(std::size_t body_count) const { return flowmpm::diagnostics(model_, body_count); }

 private:
  void run_node(const StageGroup& stages) {
    if (observer_)
      for (Stage s : stages) observer_(s);
    using S = Stage;
    auto is = [&](std::initializer_list<Stage> group) { return std::ranges::equal(stages, group); };
    if (is({S::p2g_momentum, S::p2g_force})) return p2g_momentum_and_force(model_);
    if (is({S::g2p_motion, S::g2p_stress})) return g2p_motion_and_stress(model_);
    if (stages.size() != 1) throw std::logic_error("no single pass runs the stages " + group_name(stages));
    switch (stages.front()) {
      case Stage::p2g_momentum: p2g_momentum(model_); break;
      case Stage::p2g_force: p2g_force(model_); break;
      case Stage::grid_velocity: grid_velocity(model_); break;
      case Stage::grid_integrate: grid_integrate(model_); break;
      case Stage::g2p_motion: g2p_motion(model_); break;
      case Stage::g2p_stress: g2p_stress(model_); break;
      // MUSL: mass and momentum mapped again from the updated particles.
      case Stage::remap: p2g_momentum(model_); break;
    }
  }

  template <class RunStep>
  void finish_step(RunStep&& run_step) {
    if (model_.flags.resort_needed) sort_particles(model_);
    run_step();
    if (model_.flags.failed) {
      std::ostringstream s;
      s.precision(6);
      s << "step " << model_.step + 1 << " (t = " << model_.t << " s to " << model_.t + model_.dt
        << " s): " << model_.flags.problem;
      throw SimulationError(s.str());
    }
    ++model_.step;
    // A fixed step keeps t an exact multiple of dt; an automatic one adds up.
    model_.t = fixed_dt_ > 0.0 ? static_cast<double>(model_.step) * fixed_dt_ : model_.t + model_.dt;
  }

  Model<D, Shape> model_;
  double fixed_dt_;  // 0 with an automatic time step
  std::function<void(Stage)> observer_;
  StepGraph graph_;
};

}  // namespace flowmpm
