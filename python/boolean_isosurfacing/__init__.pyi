from typing import Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

from ._core import *  # noqa: F401,F403
from ._core import IndexArray

__version__: str

@overload
def triangulate(polygons: Sequence[npt.ArrayLike], labels: None = None) -> IndexArray: ...
@overload
def triangulate(polygons: Sequence[npt.ArrayLike], labels: npt.ArrayLike) -> Tuple[IndexArray, npt.NDArray]: ...
