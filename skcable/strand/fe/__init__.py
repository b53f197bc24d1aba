"""The strand finite element: slip laws, terms and the model (mesh + bases + terms)."""

from skcable.strand.fe.annex_e import AnnexE, annex_e_forces, annex_e_section
from skcable.strand.fe.model import DAMAGE_LOADS, StrandModel, default_physics
from skcable.strand.fe.slip import AxisSlip, ElementSlip, SlipLaw, Stick, slip_law
from skcable.strand.fe.terms import (
    FIELDS,
    STRAINS,
    DistributedLoad,
    ElasticFoundation,
    FieldTerm,
    HelicalWires,
    NodalSpring,
    SectionTerm,
    SinusoidalDamageLoads,
    Step,
    Term,
    WireBending,
)

__all__ = [
    "AnnexE",
    "annex_e_forces",
    "annex_e_section",
    "DAMAGE_LOADS",
    "FIELDS",
    "STRAINS",
    "AxisSlip",
    "DistributedLoad",
    "ElasticFoundation",
    "ElementSlip",
    "FieldTerm",
    "HelicalWires",
    "NodalSpring",
    "SectionTerm",
    "SinusoidalDamageLoads",
    "SlipLaw",
    "Step",
    "Stick",
    "StrandModel",
    "Term",
    "WireBending",
    "default_physics",
    "slip_law",
]
