// How the particles' velocity is updated from the grid (docs/theory/transfers.md):
//   flip:  v_p += sum N_Ip dv_I, the grid's velocity change;
//   pic:   v_p = sum N_Ip v_I, the grid's velocity;
//   blend: flip_fraction of FLIP plus the rest of PIC;
//   apic:  PIC with an affine velocity C_p per particle, mapped back to the
//          grid with it [Jiang 2015];
//   xpic:  XPIC(m), PIC that keeps the part of the particles' velocity that
//          m grid-particle projections reach [Hammerquist 2017].
#pragma once

namespace flowmpm {

enum class VelocityUpdate { flip, pic, blend, apic, xpic };

inline const char* velocity_update_name(VelocityUpdate u) {
  switch (u) {
    case VelocityUpdate::flip: return "flip";
    case VelocityUpdate::pic: return "pic";
    case VelocityUpdate::blend: return "blend";
    case VelocityUpdate::apic: return "apic";
    case VelocityUpdate::xpic: return "xpic";
  }
  return "";
}

}  // namespace flowmpm
