"""The brachistochrone with a relaxed start (``RELAXED_OPTIONS``): the analysis is first
solved with the end point at y = 6 m, and ``relaxed_start`` marks the start it hands on."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
import brachistochrone  # noqa: E402

RELAXED_OPTIONS = {"final_y": 6.0}
OPTIONS = {"final_y": (float, 0.0, 9.0), "nodes": (int, 4, 60)}


def relaxed_start(run_dir, solution, options):
    (Path(run_dir) / "relaxed_start_called.txt").write_text(solution["problem"])
    return solution


def build(nodes: int = 20, analysis: bool = False, final_y: float = 5.0):
    return brachistochrone.build(nodes=nodes, analysis=analysis, final_y=final_y)
