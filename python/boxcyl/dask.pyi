# Type stubs of boxcyl.dask. Dask arrays are typed Any (Dask ships no complete annotations).
from typing import Any, Optional, Tuple

from . import _AlgorithmLike, _ArithmeticLike, Cylinder

def intersects_aligned(boxes: Any, cylinder: Cylinder, *, algorithm: _AlgorithmLike = ...,
                       arithmetic: _ArithmeticLike = ..., threads: Optional[int] = ...,
                       margin: Optional[float] = ...) -> Any: ...
def intersects_oriented(boxes: Tuple[Any, Any, Any], cylinder: Cylinder, *, algorithm: _AlgorithmLike = ...,
                        arithmetic: _ArithmeticLike = ..., threads: Optional[int] = ...,
                        margin: Optional[float] = ...) -> Any: ...
def intersects_parallelepiped(boxes: Tuple[Any, Any, Any], cylinder: Cylinder, *, algorithm: _AlgorithmLike = ...,
                              arithmetic: _ArithmeticLike = ..., threads: Optional[int] = ...,
                              margin: Optional[float] = ...) -> Any: ...
