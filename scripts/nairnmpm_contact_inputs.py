#!/usr/bin/env python3
"""NairnMPM inputs for the contact comparisons of docs/validation/contact.md:
Sulsky's disks and two bars meeting end on, in one velocity field and with
NairnMPM's frictionless multi-material contact, in SI units.

    scripts/nairnmpm_contact_inputs.py write DIR      one folder per run, DIR/<run>/input.xml
    scripts/nairnmpm_contact_inputs.py summary DIR    kinetic energy of each run's global archive

NairnMPM (github nairnj/nairn-mpm-fea; measured at commit 7f47b022) on
Debian: apt-get install libxerces-c-dev; in NairnMPM/build, delete the
shipped *.o files and run make SYSTEM=mpm; then, per run,
cd DIR/<run> && NairnMPM -np 2 input.xml > out/log.txt.

Every run: plane strain (analysis 10), uGIMP, 2 x 2 particles per cell,
USL (MPMMethod 3 with SkipPostExtrapolation: the strain from the updated
grid velocities; the *_usl_plus runs without it, NairnMPM's USL+), FLIP,
NairnMPM's isotropic material (type 1). NairnMPM
adds a cell on every side of the grid it is given, so each grid is given
one cell inside the domain the flowmpm case covers. No <Friction> element:
NairnMPM's default frictionless law, with its default detection and
normals unless Normals (0 max gradient, 2 average gradient, 5 linear and 6
logistic regression) or ContactPosition (a gap from positions, in cells)
are set.
"""
import glob
import os
import sys


def material(name, nu):
    return (f'  <Material Type="1" Name="{name}">\n    <rho>1000</rho>\n    <E>1000</E>\n'
            f'    <nu>{nu}</nu>\n    <alpha>0</alpha>\n  </Material>\n')


def document(run_dir, title, dt, end, grid, bodies, materials, contact, normals=None, position=None,
             usl_plus=False):
    """The input file: grid (x0, x1, y0, y1, h) is the flowmpm case's domain; usl_plus: NairnMPM's
    USL+ (the updated particle momenta extrapolated again before the strain update: MUSL)."""
    x0, x1, y0, y1, h = grid
    archive = "".join(f'    <GlobalArchive type="{q}"/>\n' for q in ("Kinetic Energy", "Strain Energy"))
    archive += "".join(f'    <GlobalArchive type="{q}" matname="{m}"/>\n'
                       for m in ("a", "b") for q in ("velx", "vely"))
    skip = "" if usl_plus else "    <SkipPostExtrapolation/>\n"
    mode = ""
    if contact:
        attributes = "" if normals is None else f' Normals="{normals}"'
        inner = "" if position is None else f"\n      <ContactPosition>{position}</ContactPosition>\n    "
        mode = f"    <MultiMaterialMode{attributes}>{inner}</MultiMaterialMode>\n"
    return f"""<?xml version='1.0'?>
<!DOCTYPE JANFEAInput>
<JANFEAInput version='3'>
  <Header>
    <Description>{title}</Description>
    <Analysis>10</Analysis>
    <ConsistentUnits length="m" mass="kg" time="s"/>
  </Header>
  <MPMHeader>
    <MPMMethod>3</MPMMethod>
{skip}    <GIMP type="uGIMP"/>
    <MatlPtsPerElement>4</MatlPtsPerElement>
    <Timing step="{dt}" max="{end}"/>
    <ArchiveRoot>{run_dir}/out/res</ArchiveRoot>
    <ArchiveTime>{end}</ArchiveTime>
    <GlobalArchiveTime>0.01</GlobalArchiveTime>
{archive}{mode}  </MPMHeader>
  <Mesh output="file">
    <Grid xmin="{x0 + h:.6g}" xmax="{x1 - h:.6g}" ymin="{y0 + h:.6g}" ymax="{y1 - h:.6g}" thickness="1">
      <Horiz cellsize="{h}"/>
      <Vert cellsize="{h}"/>
    </Grid>
  </Mesh>
  <MaterialPoints>
{bodies}  </MaterialPoints>
{materials}</JANFEAInput>
"""


def disks(run_dir, contact, **detection):
    """configs/benchmarks/sulsky_disks.toml and configs/contact/sulsky_disks_frictionless.toml."""
    bodies = ('    <Body matname="a" thick="1" vx="0.1" vy="0.1">\n'
              '      <Oval xmin="0.0" xmax="0.4" ymin="0.0" ymax="0.4"/>\n    </Body>\n'
              '    <Body matname="b" thick="1" vx="-0.1" vy="-0.1">\n'
              '      <Oval xmin="0.6" xmax="1.0" ymin="0.6" ymax="1.0"/>\n    </Body>\n')
    return document(run_dir, "Sulsky's disks", 1e-3, 3.5, (-0.05, 1.05, -0.05, 1.05, 0.05), bodies,
                    material("a", 0.3) + material("b", 0.3), contact, **detection)


def bars(run_dir, contact, h, dt):
    """configs/contact/bars_impact_frictionless.toml at cells of h."""
    bodies = ('    <Body matname="a" thick="1" vx="0.1" vy="0">\n'
              '      <Rect xmin="0.0" xmax="0.2" ymin="0.0" ymax="0.1"/>\n    </Body>\n'
              '    <Body matname="b" thick="1" vx="-0.1" vy="0">\n'
              '      <Rect xmin="0.3" xmax="0.5" ymin="0.0" ymax="0.1"/>\n    </Body>\n')
    return document(run_dir, "two bars meeting end on", dt, 1.5, (-0.35, 0.95, -0.05, 0.15, h), bodies,
                    material("a", 0) + material("b", 0), contact)


# Two materials of equal properties in one field without MultiMaterialMode:
# the one-field runs (the names only let each body's velocity be archived).
RUNS = {
    "disks_one_field": lambda d: disks(d, False),
    "disks_contact": lambda d: disks(d, True),
    "disks_contact_linear_regression": lambda d: disks(d, True, normals=5),
    "disks_contact_average_gradient": lambda d: disks(d, True, normals=2),
    "disks_contact_average_gradient_position_0.8": lambda d: disks(d, True, normals=2, position=0.8),
    "disks_contact_max_gradient": lambda d: disks(d, True, normals=0),
    "disks_one_field_usl_plus": lambda d: disks(d, False, usl_plus=True),
    "disks_contact_usl_plus": lambda d: disks(d, True, usl_plus=True),
    "bars_one_field_h0.05": lambda d: bars(d, False, 0.05, 1e-3),
    "bars_contact_h0.05": lambda d: bars(d, True, 0.05, 1e-3),
    "bars_one_field_h0.0125": lambda d: bars(d, False, 0.0125, 2.5e-4),
    "bars_contact_h0.0125": lambda d: bars(d, True, 0.0125, 2.5e-4),
}


def write(root):
    for name, make in RUNS.items():
        run_dir = os.path.abspath(os.path.join(root, name))
        os.makedirs(os.path.join(run_dir, "out"), exist_ok=True)
        with open(os.path.join(run_dir, "input.xml"), "w") as f:
            f.write(make(run_dir))
    print("\n".join(RUNS))


def summary(root):
    """Per run: the kinetic energy over the first record's, at the end and its
    mean over the last 0.5 s (disks) or 0.3 s (bars), and the restitution of
    the bodies' mean velocities, e = -(V_b - V_a) . u0 / |u0|^2 with u0 the
    first record's V_b - V_a (flowmpm's elastic_impact measure)."""
    print(f"{'run':46s} {'t_end':>6s} {'KE_end/KE0':>10s} {'mean KE/KE0':>11s} {'restitution':>11s}")
    for path in sorted(glob.glob(os.path.join(root, "*", "out", "res.global"))):
        # Columns: t, kinetic, strain, velx a, vely a, velx b, vely b.
        rows = [[float(x) for x in line.split()] for line in open(path) if not line.startswith("#")]
        t, ke = [r[0] for r in rows], [r[1] for r in rows]
        window = 0.5 if t[-1] > 3 else 0.3
        late = [k / ke[0] for tt, k in zip(t, ke) if tt >= t[-1] - window - 1e-9]
        u0 = (rows[0][5] - rows[0][3], rows[0][6] - rows[0][4])
        u = (rows[-1][5] - rows[-1][3], rows[-1][6] - rows[-1][4])
        e = -(u[0] * u0[0] + u[1] * u0[1]) / (u0[0] ** 2 + u0[1] ** 2)
        print(f"{path.split(os.sep)[-3]:46s} {t[-1]:6.3f} {ke[-1] / ke[0]:10.4f} {sum(late) / len(late):11.4f} {e:11.4f}")


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in ("write", "summary"):
        sys.exit(__doc__)
    (write if sys.argv[1] == "write" else summary)(sys.argv[2])
