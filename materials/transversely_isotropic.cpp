#include "materials/transversely_isotropic.hpp"

#include <sstream>
#include <string>

#include "core/parameter_table.hpp"

namespace flowmpm {

TransverselyIsotropic TransverselyIsotropic::read(ParameterTable& t) {
  Orthotropic::Parameters p;
  p.density = t.number("density");
  t.require(p.density > 0.0, "density", "a positive density in kg/m^3");
  const std::string axis = t.choice("axis", {"z", "y"});
  auto modulus = [&](const char* key, const char* what) {
    const double v = t.number(key);
    t.require(v > 0.0, key, std::string("a positive ") + what + " in Pa");
    return v;
  };
  const double EA = modulus("EA", "axial Young's modulus");
  const double ET = modulus("ET", "transverse Young's modulus");
  const double GA = modulus("GA", "axial shear modulus");
  if (t.has("nuAT") && t.has("nuTA")) {
    t.fail("nuTA", "only one of nuAT and nuTA (the other follows from nuAT / EA = nuTA / ET)");
  }
  if (!t.has("nuAT") && !t.has("nuTA")) t.fail("nuAT", "one axial Poisson ratio, nuAT or nuTA");
  const char* axial_key = t.has("nuAT") ? "nuAT" : "nuTA";
  const double nuAT = t.has("nuAT") ? t.number("nuAT") : t.number("nuTA") * EA / ET;
  const double nuT = t.number("nuT");
  t.require(nuT > -1.0 && nuT < 1.0, "nuT", "a transverse Poisson ratio in (-1, 1)");
  // Positive definite compliance: (1 + nuT)(1 - nuT - 2 nuAT nuTA) > 0.
  const double nuTA = nuAT * ET / EA;
  if (2.0 * nuAT * nuTA >= 1.0 - nuT) {
    std::ostringstream s;
    s << "an axial Poisson ratio with 2 nuAT nuTA < 1 - nuT (here 2 nuAT nuTA = " << 2.0 * nuAT * nuTA
      << ", 1 - nuT = " << 1.0 - nuT << "): otherwise the compliance is not positive definite";
    t.fail(axial_key, s.str());
  }
  const double GT = ET / (2.0 * (1.0 + nuT));
  if (axis == "z") {
    p.Ex = p.Ey = ET;
    p.Ez = EA;
    p.Gxz = p.Gyz = GA;
    p.Gxy = GT;
    p.nuxy = nuT;
    p.nuxz = p.nuyz = nuTA;  // nu_xz = nu_zx Ex / Ez
  } else {
    p.Ex = p.Ez = ET;
    p.Ey = EA;
    p.Gxy = p.Gyz = GA;
    p.Gxz = GT;
    p.nuxz = nuT;
    p.nuxy = nuTA;  // nu_xy = nu_yx Ex / Ey
    p.nuyz = nuAT;
  }
  // alpha = [axial, transverse]; beta, conductivity and diffusivity likewise.
  read_transport_and_expansion(t, p, axis == "z" ? transverse_axes_z : transverse_axes_y);
  return TransverselyIsotropic(Orthotropic(p));
}

}  // namespace flowmpm
