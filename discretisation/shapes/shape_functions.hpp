// The registry of shape functions: each is a type with
//   static constexpr const char* name;     // the case file's analysis.shape_function
//   static constexpr int support;          // nodes per axis of its 1D stencil
//   static constexpr int reach_below, reach_above;  // nodes c - below ... c + above of cell c
//   static constexpr bool gradient_jumps;  // the gradient stays finite where N vanishes (linear)
//   static constexpr double apic_inertia;  // APIC's D_p in h^2 where it is the same for every
//                                          // particle (B-splines), 0 where it is not (linear, GIMP:
//                                          // APIC takes the velocity gradient there)
//   static constexpr std::array<double, 4> stable_factor_usl, stable_factor_remapped;
//                                          // largest stable dt in h / c, 1 to 4 particles per cell
//   static void stencil(double g, double inv_h, double half_width, int& base,
//                       double (&w)[support], double (&dw)[support]);
// Adding one is one new file and one line in the list below; the engine is
// compiled for each (a template parameter of the hot loops).
#pragma once
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "discretisation/shapes/shape_bspline.hpp"
#include "discretisation/shapes/shape_gimp.hpp"
#include "discretisation/shapes/shape_linear.hpp"

namespace flowmpm {

template <class... Shapes>
struct ShapeList {
  static std::vector<std::string> names() { return {Shapes::name...}; }
};

// The registry: X(Shape) for each shape function. The engine is compiled
// for each (engine/simulation.hpp); ShapeFunctions lists the same types.
#define FLOWMPM_SHAPE_FUNCTIONS(X) X(LinearShape) X(GimpShape) X(QuadraticBSpline) X(CubicBSpline)

namespace detail {
template <class List>
struct without_first;
template <class First, class... Rest>
struct without_first<ShapeList<First, Rest...>> {
  using type = ShapeList<Rest...>;
};
#define FLOWMPM_SHAPE_TYPE(Shape) , Shape
}  // namespace detail

using ShapeFunctions = detail::without_first<ShapeList<void FLOWMPM_SHAPE_FUNCTIONS(FLOWMPM_SHAPE_TYPE)>>::type;

inline std::vector<std::string> shape_function_names() { return ShapeFunctions::names(); }

// A shape function chosen when the case is read: its place in
// ShapeFunctions. Nothing after the reader looks a shape function up by name.
struct ShapeChoice {
  std::size_t index = 0;  // LinearShape
  friend bool operator==(ShapeChoice, ShapeChoice) = default;
};

namespace detail {
template <class F, class First, class... Rest>
decltype(auto) with_shape_in(std::size_t index, F& f, ShapeList<First, Rest...>) {
  if (index == 0) return f.template operator()<First>();
  if constexpr (sizeof...(Rest) > 0) {
    return with_shape_in(index - 1, f, ShapeList<Rest...>{});
  } else {
    throw std::invalid_argument("no shape function " + std::to_string(index));
  }
}
}  // namespace detail

// Calls f.template operator()<Shape>() for the chosen shape function.
template <class F>
decltype(auto) with_shape_function(ShapeChoice shape, F&& f) {
  return detail::with_shape_in(shape.index, f, ShapeFunctions{});
}

// The shape function called `name` (the case file's
// analysis.shape_function); throws std::invalid_argument if none is.
inline ShapeChoice shape_function_named(std::string_view name) {
  const std::vector<std::string> names = shape_function_names();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return {i};
  throw std::invalid_argument("unknown shape function \"" + std::string(name) + "\"");
}

inline const char* shape_function_name(ShapeChoice shape) {
  return with_shape_function(shape, []<class Shape>() { return Shape::name; });
}

// Calls f.template operator()<D>() for a dimension, 1, 2 or 3.
template <class F>
decltype(auto) with_dimension(int dimension, F&& f) {
  switch (dimension) {
    case 1: return f.template operator()<1>();
    case 2: return f.template operator()<2>();
    case 3: return f.template operator()<3>();
  }
  throw std::invalid_argument("dimension " + std::to_string(dimension) + " is not 1, 2 or 3");
}

// Calls f.template operator()<D, Shape>() for a dimension (1, 2 or 3) and a
// shape function: the one dispatch from run-time choices to compiled code.
template <class F>
decltype(auto) with_dimension_and_shape(int dimension, ShapeChoice shape, F&& f) {
  return with_shape_function(shape, [&]<class Shape>() -> decltype(auto) {
    return with_dimension(dimension, [&]<int D>() -> decltype(auto) { return f.template operator()<D, Shape>(); });
  });
}

}  // namespace flowmpm
