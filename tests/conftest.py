import sys
from pathlib import Path

# let test modules import each other's helpers (e.g. test_nlp_harness.BRACH)
sys.path.insert(0, str(Path(__file__).parent))
