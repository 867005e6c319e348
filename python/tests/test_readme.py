"""The main README's Python examples run as written: the quick start, then the batch and Dask block,
in order and in one scope (the second uses the quick start's `cyl`)."""
import re
from pathlib import Path

import numpy as np

README = Path(__file__).resolve().parents[2] / "README.md"


def test_readme_python_blocks_run():
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), re.S)
    assert len(blocks) == 2, "README.md: expected the quick start and the batch block"
    scope = {}
    exec(compile(blocks[0], "README.md (quick start)", "exec"), scope)
    # The cylinder touches the box's face x = 1; one double further away it misses.
    assert scope["touching"] is True
    assert scope["apart"] is False
    exec(compile(blocks[1], "README.md (batches and Dask)", "exec"), scope)
    assert scope["hits"].tolist() == [True, False]
    assert scope["near"].tolist() == [True, True]  # the second box's face x = 0.5 is 0.5 from the side
    assert scope["count"] == 500_000
    assert isinstance(scope["hits"], np.ndarray)
