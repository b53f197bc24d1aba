"""Print pip constraints that pin each runtime dependency of pyproject.toml to its floor.

``name>=X`` becomes ``name==X``: the oldest versions the project says it supports, so that
CI can install them (``pip install -c <this output> ".[test]"``) and run the suite on them
beside the newest. One source: the floors are read from pyproject.toml, never written twice.
"""

import re
import sys
import tomllib
from pathlib import Path

project = tomllib.loads((Path(__file__).parents[1] / "pyproject.toml").read_text())["project"]
for requirement in project["dependencies"]:
    if ";" in requirement:  # an environment marker: not for this interpreter's floor set
        continue
    found = re.fullmatch(r"\s*([A-Za-z0-9_.\-]+)\s*>=\s*([0-9][^,\s]*)\s*", requirement)
    if found is None:
        sys.exit(f"oldest_constraints: {requirement!r} has no plain '>=' floor")
    print(f"{found[1]}=={found[2]}")
