"""libelastica: Euler's elastica for CAD — exact evaluation, fairing, Hermite
interpolation, B-splines (Python binding of the C library)."""
from ._ffi import DomainError, ElasticaError, NotConvergedError, SingularError
from .core import DiscreteElastica, SmoothElastica

__version__ = "0.1.0"
