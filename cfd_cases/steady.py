"""The CFD's steady test: the shared implementation is :mod:`kegel.steady` (the dynamic solution
uses it too); this module keeps the names the CFD code and its users import."""

from kegel.solutions.steady import SteadyDrift, SteadyTest, drift_of_means, first_steady_time, steady_drift, window_means

__all__ = ["SteadyDrift", "SteadyTest", "drift_of_means", "window_means", "steady_drift", "first_steady_time"]
