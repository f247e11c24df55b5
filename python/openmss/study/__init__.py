"""Design studies on Dask: parameter sweeps and designs of experiments over an ADAMS data set.

A study file (YAML, docs/studies.md) names a data set or command file, the statement
arguments to vary (``SPRINGDAMPER/3.K``, ``VARIABLE/7.FUNCTION``), their values and the
outputs to collect from each variant's request file. Every variant runs the C++ ``openmss``
program with ``--set`` overrides in a folder of its own, as a task on a Dask cluster (a
LocalCluster on this machine, or a running scheduler), and the results gather into one CSV
table that is identical for any worker count and completion order.
"""

from .spec import Study, StudyError, load_study
from .design import variants
from .execute import run_study

__all__ = ["Study", "StudyError", "load_study", "variants", "run_study"]
