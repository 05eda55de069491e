"""Problem assembly on ``casadi.Opti``: scaled variables, named constraint groups,
IPOPT solve with the log in a file, solutions by name and unit, run folders."""
from .problem import ConstraintGroup, Problem, Solution, SolveError, Variable
from .run import RunError, load_problem_file, run_problem

__all__ = ["Problem", "Solution", "SolveError", "Variable", "ConstraintGroup",
           "RunError", "load_problem_file", "run_problem"]
