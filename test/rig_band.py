"""The band a load-controlled rig holds, shared by the rostests that put the example controller in
the loop (test_rig_controller.py running, test_rig_stepped.py stepped): after SETTLE seconds of
simulated time, the mean calibrated horizontal load over each further WINDOW lies within +-BAND of
the set point. The load of a breaking, riding-up ice sheet swings by more than that from one 10 ms
sample to the next, so the band is on window means, which is what a load-controlled rig holds.
"""
SETTLE = 2.0   # [s] of simulated time before the band applies
WINDOW = 0.5   # [s] of simulated time per mean
END = 4.0      # [s] of simulated time observed
BAND = 0.5     # relative half-width of the band


def assert_load_in_band(test, data, set_point):
    """data: (stamp [s], calibrated horizontal load [N]) per wrench message. Prints every window's
    mean, then asserts the band on those after SETTLE."""
    means = []
    t0 = 0.0
    while t0 + WINDOW <= END + 1e-9:
        w = [f for t, f in data if t0 <= t < t0 + WINDOW]
        means.append("%.1f-%.1f s: %.0f N" % (t0, t0 + WINDOW, sum(w) / len(w) if w else float("nan")))
        t0 += WINDOW
    print("window means: " + ", ".join(means))
    start = SETTLE
    while start + WINDOW <= END + 1e-9:
        window = [f for t, f in data if start <= t < start + WINDOW]
        test.assertTrue(window, "no samples in [%.2f, %.2f) s" % (start, start + WINDOW))
        mean = sum(window) / len(window)
        test.assertLess(abs(mean - set_point), BAND * set_point,
                        "mean load %.1f N in [%.2f, %.2f) s is outside %.0f N +- %.0f %%"
                        % (mean, start, start + WINDOW, set_point, 100 * BAND))
        start += WINDOW
