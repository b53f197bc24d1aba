"""The strand finite element: the term protocol, slip laws, the built-in physics, ready terms
(foundations, contact, loads anywhere), supports and the model (mesh + bases + supports + terms).
"""

from skcable.strand.fe.annex_e import AnnexE, annex_e_forces, annex_e_section
from skcable.strand.fe.cycles import BendingCycles, bending_cycles
from skcable.strand.fe.foundations import ElasticFoundation, NodalSpring, RigidCylinder, TensionlessFoundation
from skcable.strand.fe.loads import FollowerForce, PointForce, PointMoment, TransverseLoad
from skcable.strand.fe.model import DAMAGE_LOADS, ELEMENTS, StrandModel, default_physics
from skcable.strand.fe.slip import AxisSlip, ElementSlip, SlipLaw, SlipPoints, Stick, slip_law
from skcable.strand.fe.stages import StageSlip
from skcable.strand.fe.supports import AXIAL_LOADS, DOFS, END_CONDITIONS, StrandSupports
from skcable.strand.fe.terms import FIELDS, STRAINS, FieldAssembly, FieldTerm, SectionTerm, Step, Term
from skcable.strand.fe.wires import HelicalWires, SinusoidalDamageLoads, WireBending, critical_curvature_table

__all__ = [
    "AXIAL_LOADS",
    "AnnexE",
    "AxisSlip",
    "BendingCycles",
    "DAMAGE_LOADS",
    "DOFS",
    "ELEMENTS",
    "END_CONDITIONS",
    "ElasticFoundation",
    "ElementSlip",
    "FIELDS",
    "FieldAssembly",
    "FieldTerm",
    "FollowerForce",
    "HelicalWires",
    "NodalSpring",
    "PointForce",
    "PointMoment",
    "RigidCylinder",
    "STRAINS",
    "SectionTerm",
    "SinusoidalDamageLoads",
    "SlipLaw",
    "SlipPoints",
    "Step",
    "StageSlip",
    "Stick",
    "StrandModel",
    "StrandSupports",
    "TensionlessFoundation",
    "Term",
    "TransverseLoad",
    "WireBending",
    "annex_e_forces",
    "bending_cycles",
    "annex_e_section",
    "critical_curvature_table",
    "default_physics",
    "slip_law",
]
