"""The brachistochrone with a relaxed start in two steps (``RELAXED_OPTIONS`` a list): the analysis
is solved with the end point at y = 6 m, then at 5.5 m, and ``relaxed_start`` records, after each
step, the options it was given (those of the solve it starts) and those the step was flown with."""
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
import brachistochrone  # noqa: E402

RELAXED_OPTIONS = [{"final_y": 6.0}, {"final_y": 5.5}]
OPTIONS = {"final_y": (float, 0.0, 9.0), "nodes": (int, 4, 60)}


def relaxed_start(run_dir, solution, options):
    flown = json.loads((Path(run_dir) / "summary.json").read_text())["options"]
    (Path(run_dir) / "relaxed_start_called.json").write_text(json.dumps({"next": options, "flown": flown}))
    return solution


def build(nodes: int = 20, analysis: bool = False, final_y: float = 5.0):
    return brachistochrone.build(nodes=nodes, analysis=analysis, final_y=final_y)
