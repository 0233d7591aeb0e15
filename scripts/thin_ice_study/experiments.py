"""The experiments the simulator is validated against, read from config/experiments.yaml (the one
place their figures are written; the C++ tools embed the same file when they are built), and the
paper's calibration factor alpha of Eq. (18) with which Table 6 compares with them, read from the
scenarios' base file (where the seven series inherit it from; quick.yaml, a test scenario kept
whole so that tests can copy it alone, states the same value)."""
import os

import yaml

from . import ROOT, scenario_file

_PATH = os.path.join(ROOT, "config", "experiments.yaml")

with open(_PATH) as _f:
    _DATA = yaml.safe_load(_f)

STRUCTURE_WIDTH = float(_DATA["structure_width"])  # [m]
PHASE1_SLOPE = float(_DATA["phase1_slope"])        # [N/m] on the experiments' structure
# Per ice type letter ("W", "M", "S"): steady mean and peak [N] on the experiments' structure.
STEADY_MEAN = {k: float(v["steady_mean"]) for k, v in _DATA["ice_types"].items()}
PEAK = {k: float(v["peak"]) for k, v in _DATA["ice_types"].items()}
ICE_TYPE = {k: v["name"] for k, v in _DATA["ice_types"].items()}
# The paper's own simulation (Table 6, TIM): (peak, steady mean) [N].
PAPER_TIM = {k: (v["paper_tim"]["peak"], v["paper_tim"]["steady_mean"]) for k, v in _DATA["ice_types"].items()}
PUSHED_LENGTH = {k: float(v) for k, v in _DATA["pushed_length"].items()}  # [m] per series (Table 5)
# alpha [-] of Eq. (18), the paper's one factor (Section 5.1.1): structure.calibration_factor of
# config/scenarios/base/tank.yaml. Runs recorded with another alpha are rescaled to it in the reports
# (run_record.at_alpha).
ALPHA = float(scenario_file.load(os.path.join(ROOT, "config", "scenarios", "base", "tank.yaml"))
              ["structure"]["calibration_factor"])


def per_metre(value):
    """A load on the experiments' structure [N] as a load per metre of its width [N/m]."""
    return value / STRUCTURE_WIDTH
