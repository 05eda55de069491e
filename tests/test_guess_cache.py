"""The rotor-speed guesses are computed once per process for a repeated build (``mdo run``
builds the baseline and then the optimization): the second build's initial point is the
first's, and a changed input is computed afresh."""
import numpy as np

from mdo.nlp import load_problem_file
from mdo.vehicle import guess


def _x0(problem):
    return np.asarray(problem.opti.debug.value(problem.opti.x, problem.opti.initial()), float).ravel()


def test_second_build_reuses_the_rotor_guesses_and_is_identical():
    guess._OMEGA_CACHE.clear()
    calls = []
    orig = guess._omega_for_thrust

    def counting(gm, *a, **k):
        calls.append(gm)
        return orig(gm, *a, **k)

    guess._omega_for_thrust = counting
    try:
        first = load_problem_file("problems/ga2p.py", analysis=True)
        n_first = len(calls)
        second = load_problem_file("problems/ga2p.py")
        assert n_first > 0 and len(calls) == n_first          # nothing recomputed
        assert np.array_equal(_x0(first), _x0(second))
        guess._OMEGA_CACHE.clear()                              # without the store: the same point
        third = load_problem_file("problems/ga2p.py")
        assert len(calls) == 2 * n_first
        assert np.array_equal(_x0(second), _x0(third))
    finally:
        guess._omega_for_thrust = orig

    gm = calls[0]
    T = np.array([900.0, 1200.0])
    args = (np.array([40.0, 50.0]), np.zeros(2), np.array([300.0, 600.0]), np.zeros(2))
    w1 = guess.omega_for_thrust(gm, T, *args)
    w1[:] = -1.0                                                # the caller's copy, not the store's
    w2 = guess.omega_for_thrust(gm, T, *args)
    assert np.all(w2 > 0)
    w3 = guess.omega_for_thrust(gm, 1.1 * T, *args)
    assert np.all(w3 > w2)                                      # more thrust, more speed: recomputed


def test_climbing_scan_brackets_the_lowest_speed_and_threads_change_no_number(monkeypatch):
    """The rotor-speed search climbs its grid only as far as each node needs: its answer is
    the root in the interval of the lowest grid speed whose thrust reaches T1 (the whole
    grid evaluated here as the reference), and the numeric BEMT split over two threads gives
    the same numbers to the bit."""
    seen = []
    orig = guess._omega_for_thrust
    monkeypatch.setattr(guess, "_omega_for_thrust", lambda gm, *a: seen.append(gm) or orig(gm, *a))
    guess._OMEGA_CACHE.clear()
    load_problem_file("problems/ga2p.py", analysis=True)
    monkeypatch.setattr(guess, "_omega_for_thrust", orig)
    gm = seen[0]
    T = np.array([300.0, 900.0, 1500.0, 2600.0])
    args = (np.array([20.0, 45.0, 60.0, 70.0]), np.zeros(4), np.array([0.0, 300.0, 900.0, 2000.0]), np.zeros(4))
    guess._OMEGA_CACHE.clear()
    monkeypatch.setenv("MDO_THREADS", "1")
    w1 = guess._omega_for_thrust(gm, T, *args)
    monkeypatch.setenv("MDO_THREADS", "2")
    w2 = guess._omega_for_thrust(gm, T, *args)
    assert np.array_equal(w1, w2)
    grid = guess.speed_grid(gm)
    K = T.size
    full = np.asarray(guess.bemt_numeric(gm, np.repeat(grid, K), *(np.tile(a, grid.size) for a in args))
                      ["thrust_N"], float).reshape(grid.size, K)
    for k in range(K):
        j = int(np.argmax(full[:, k] >= T[k]))
        assert j > 0 and full[j, k] >= T[k] > full[j - 1, k]
        assert grid[j - 1] < w1[k] <= grid[j]
    Tw = np.asarray(guess.bemt_numeric(gm, w1, *args)["thrust_N"], float).ravel()
    assert np.allclose(Tw, T, rtol=1e-9)
