# Type stubs of impact3d (the docstrings are in __init__.py).
import os
from typing import Any, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

from ._impact3d import (BATCH_COLUMNS as BATCH_COLUMNS, BATCH_SIMD as BATCH_SIMD, PRECISIONS as PRECISIONS,
                        REGIMES as REGIMES, STATUSES as STATUSES, WARNINGS as WARNINGS, Case as Case,
                        CaseError as CaseError)

CaseLike = Union[str, os.PathLike[str], dict[str, Any], Case]
Strategies = Optional[Union[str, dict[str, Any], Sequence[Union[str, dict[str, Any]]]]]
Column = Union[float, npt.ArrayLike]

def read_case(case: CaseLike) -> Case: ...
def solve(case: CaseLike, strategies: Strategies = None, engine: str = "generated", precision: str = "double",
          units: Optional[str] = None) -> dict[str, Any]: ...
def solve_batch(jobs: int = 0, velocities: bool = False, strategy: str = "pc-crash", limit: Optional[str] = None,
                **columns: Column) -> dict[str, Any]: ...
def montecarlo(case: CaseLike, uncertainty: Union[str, os.PathLike[str], dict[str, Any]], strategies: Strategies = None,
               precision: str = "double", engine: str = "generated", jobs: int = 0, samples: Optional[int] = None,
               seed: Optional[int] = None, keep_samples: bool = False) -> dict[str, Any]: ...
def sensitivity(case: CaseLike, strategies: Strategies = None, engine: str = "generated") -> dict[str, Any]: ...
def reconstruct(case: CaseLike, evidence: Union[str, os.PathLike[str], dict[str, Any]],
                strategy: Optional[Union[str, dict[str, Any]]] = None, engine: str = "generated") -> dict[str, Any]: ...
