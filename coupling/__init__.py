"""Coupling of friction and hydraulic losses and flow-force feedback into the MBS.

Mapped into the import package as ``kegel.coupling``. :mod:`.flow_forces` fits closed-form
flow-force laws to a correlation or to CFD results (levels from the point's result, speed exponents
fitted over the CFD speed sweep) and hands them to the dynamic simulation as
force elements, so the oil acts on the rollers and the cage; :mod:`.cfd_results` finds the CFD
result of an operating point and its contact / CFD boundary; :mod:`.split` gives what the CFD
counts beyond that boundary that the contact model does not (the far field on the unloaded
stretch of the lines); :mod:`.supply` the oil supply of the raceway contacts.
"""

from .cfd_results import cfd_loss_at, cfd_result_files, find_cfd_result, read_cfd_results
from .flow_forces import CfdFlowForceLaw, FlowForceLaw, PowerLaw, flow_forces_from_cfd, flow_forces_from_correlation
from .split import UnloadedLineWedge, unloaded_line_wedge

__all__ = ["CfdFlowForceLaw", "FlowForceLaw", "PowerLaw", "UnloadedLineWedge", "cfd_loss_at", "cfd_result_files",
           "find_cfd_result", "flow_forces_from_cfd", "flow_forces_from_correlation", "read_cfd_results",
           "unloaded_line_wedge"]
