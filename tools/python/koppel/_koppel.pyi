# Type stubs of koppel's compiled part (tools/python/module.cpp).
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

Number = Union[int, float]
Overrides = Optional[Dict[str, Union[Number, str]]]

class InputError(ValueError):
    file: str
    line: int
    column: int
    field: str
    diagnostics: List[Dict[str, Any]]

class SweepTable:
    status: str
    complete: bool
    message: str
    notes: List[str]
    order: int
    columns: List[str]
    units: List[str]
    values: npt.NDArray[np.float64]
    valid_order: npt.NDArray[np.float64]
    singular_points: List[Dict[str, Any]]
    gaps: List[Tuple[float, float]]
    def __getitem__(self, name: str) -> npt.NDArray[np.float64]: ...
    def __len__(self) -> int: ...
    def to_dict(self) -> Dict[str, npt.NDArray[np.float64]]: ...
    def brief(self) -> str: ...

class Pose:
    status: str
    ok: bool
    message: str
    input: float
    columns: List[str]
    valid_order: int
    singular: bool
    def __getitem__(self, name: str) -> float: ...
    def to_dict(self) -> Dict[str, float]: ...
    def brief(self) -> str: ...

class DeadCentres:
    status: str
    message: str
    points: List[Dict[str, Any]]
    has_stroke: bool
    stroke: float
    input_a: float
    input_i: float
    value_a: float
    value_i: float
    forward_angle: float
    phase_ratio: float
    time_ratio: float
    has_extremes: bool
    minimum: Optional[Dict[str, Any]]
    maximum: Optional[Dict[str, Any]]
    extremes_message: str
    unresolved: List[float]
    singular_points: List[Dict[str, Any]]
    gaps: List[Tuple[float, float]]
    def brief(self) -> str: ...

class Ranges:
    status: str
    message: str
    notes: List[str]
    branches: List[Dict[str, Any]]
    def brief(self) -> str: ...

class Mechanism:
    @staticmethod
    def load(path: str, *, set: Overrides = None) -> Mechanism: ...
    @staticmethod
    def parse(text: str, name: str = "<string>", *, set: Overrides = None) -> Mechanism: ...
    name: str
    title: str
    path: str
    notes: List[str]  # what admitting the mechanism noted (mobility 1 is required: InputError otherwise)
    input_name: str
    input_is_angle: bool
    outputs: List[str]
    parameters: Dict[str, float]
    assembled: bool
    def set(self, name: str, value: Union[Number, str]) -> None: ...
    def assemble(self, order: int = 2) -> Pose: ...
    def move_to(self, input: float, order: int = 2, at_branch_point: str = "continue") -> Pose: ...
    def sweep(self, start: Optional[float] = None, stop: Optional[float] = None, step: Optional[float] = None, *,
              order: int = 2, at_branch_point: str = "continue") -> SweepTable: ...
    def dead_centres(self, output: str = "", start: Optional[float] = None, stop: Optional[float] = None,
                     step: Optional[float] = None) -> DeadCentres: ...
    def range(self, *, all_branches: bool = False, at_branch_point: str = "continue") -> Ranges: ...
    def singular_positions(self) -> List[Dict[str, Any]]: ...
    def curvature(self, point: str, *, at: float) -> Dict[str, Any]: ...
    def poles(self, *, at: float) -> Dict[str, Any]: ...
    def centrodes(self, link: str, *, reference: str = "", start: Optional[float] = None, stop: Optional[float] = None,
                  step: float = 1.0, at: float = 0.0) -> Dict[str, Any]: ...
    def tolerance(self, output: str, *, inputs: Sequence[float], tol: Dict[str, float] = ..., clearance: Dict[str, float] = ...,
                  samples: int = 0, seed: int = 1, distribution: str = "uniform", threads: int = 0) -> Dict[str, Any]: ...
    def to_yaml(self) -> str: ...

class CatalogEntry:
    id: str
    title: str
    title_de: str
    path: str
    kind: str
    classes: List[str]
    links: int
    joints: int
    revolute: int
    prismatic: int
    def load(self, *, set: Overrides = None) -> Mechanism: ...

def _catalog_find(counts: Dict[str, Any], kind: str, klass: str, motion: str, text: str, directory: str) -> List[CatalogEntry]: ...
def _catalog_directory() -> str: ...
def _crank_rocker(phi0: float, psi0: float, rocker_sense: str, beta: Optional[float], lambda_: Optional[float], frame: float,
                  sense: str) -> Dict[str, Any]: ...
def _slider_crank(phi0: float, stroke: float, offset: Optional[float], beta: Optional[float]) -> Dict[str, Any]: ...
def _mzc(lambda_: Optional[float], kappa: Optional[float], diameter: float) -> Dict[str, Any]: ...
def _function(f: Callable[[float], float], type: str, x_from: float, x_to: float, in_from: float, in_to: float,
              out_from: float, out_to: float, points: int, at: Sequence[float], frame: float) -> Dict[str, Any]: ...
def _fit(problem: str, threads: int) -> Dict[str, Any]: ...
def _motion(poses: Sequence[Tuple[float, float, float]], circle_points: Sequence[Tuple[float, float]], crank_turn: float,
            curve_samples: int, require_crank: bool, threads: int) -> Dict[str, Any]: ...
