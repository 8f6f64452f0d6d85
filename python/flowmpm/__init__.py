"""flowmpm from Python: write and change cases, check and run them, read
their results into numpy by particle id, and a sweep into one table.

    import flowmpm
    case = flowmpm.Case.load("configs/uniaxial_stress/case1_usl.toml")
    case.set("analysis.dt", 0.001)
    results = flowmpm.run(case, output="results/try")
    stress = results.field("stress", step=-1, body="block")   # Pa, rows by id

Guide: docs/guide/python.md. Needs numpy and h5py (Debian's python3-numpy,
python3-h5py); pandas and matplotlib are optional.
"""
from .case import Case
from .engine import check, program, run, sweep
from .errors import CaseError, FlowmpmError, SimulationError
from .results import Results
from .sweep import Sweep

__all__ = ["Case", "CaseError", "FlowmpmError", "Results", "SimulationError", "Sweep", "check", "program", "run",
           "sweep"]
