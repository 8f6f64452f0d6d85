#include "materials/material.hpp"

#include <optional>

#include "io/case_reader.hpp"
#include "materials/parameter_reading.hpp"

namespace flowmpm {

LinearElastic LinearElastic::read(TableReader& t) {
  Parameters p;
  std::tie(p.density, p.youngs_modulus, p.poisson_ratio) = read_isotropic_elasticity(t);
  return LinearElastic(p);
}

namespace {

// Reads the model whose type_name is `type`, trying each alternative of
// the Material variant in turn.
template <class... Models>
std::optional<Material> read_model(const std::string& type, TableReader& t, std::variant<Models...>*) {
  std::optional<Material> result;
  ((type == Models::type_name ? void(result.emplace(Models::read(t))) : void()), ...);
  return result;
}

template <class... Models>
std::string type_names(std::variant<Models...>*) {
  std::string names;
  ((names += (names.empty() ? "\"" : ", \"") + std::string(Models::type_name) + "\""), ...);
  return names;
}

}  // namespace

std::string material_type_names() { return type_names(static_cast<Material*>(nullptr)); }

Material read_material(TableReader& t) {
  const std::string type = t.string("type");
  std::optional<Material> material = read_model(type, t, static_cast<Material*>(nullptr));
  if (!material) t.fail("type", "a material type, one of " + material_type_names());
  t.reject_unknown_keys();
  return *material;
}

}  // namespace flowmpm
