// A model whose update needs its neighbours (a nonlocal regularisation) may
// declare all of
//   double nonlocal_length() const;              // l (m); 0: no average needed
//   double nonlocal_source(const State&) const;  // the quantity averaged
//   bool nonlocal_read(const State&) const;      // whether the update that
//                                                // ended in this state used it
// and then its update gets, in MaterialInput, the Gaussian average over a
// few l of its neighbours' sources at the end of the same step, and its own
// weight in that average (discretisation/nonlocal/nonlocal_average.hpp). The engine
// may run the update more than once per step, from the same start, until
// the average settles (tasks/nonlocal_settle.hpp). A scene whose models ask
// for no average stores nothing and wires no stage for it.
#pragma once
#include <concepts>

namespace flowmpm {

template <class M>
concept NonlocalModel = requires(const M& m, const typename M::State& s) {
  { m.nonlocal_length() } -> std::convertible_to<double>;
  { m.nonlocal_source(s) } -> std::convertible_to<double>;
  { m.nonlocal_read(s) } -> std::convertible_to<bool>;
};

}  // namespace flowmpm
