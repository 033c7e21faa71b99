"""The binding's own warnings, kept quiet or collected in one thread only.

warnings.catch_warnings swaps the process's filters and showwarning: while one thread's
fit ignored its ConvergenceWarning, another thread's were dropped too, or caught and said
again at the wrong line (g2quad fixed that for itself in 5f302c0 with a list passed down).
Here the scopes live in a context variable, which each thread (and asyncio task) has of
its own: :func:`quiet` opens one, :func:`say` (the binding's warnings.warn) honours the
innermost that takes the warning's category, else warns as warnings.warn does, under the
caller's filters. Warnings not said through :func:`say` (numpy's) are not affected."""
from __future__ import annotations

import contextvars
import warnings
from contextlib import contextmanager
from typing import Optional

__all__ = []

# the open scopes, outermost first: (categories, the list they go to or None: dropped)
_SCOPES = contextvars.ContextVar("libelastica_quiet_scopes", default=())


@contextmanager
def quiet(*categories, into: Optional[list] = None):
    """Within, in this thread only, the binding's warnings of ``categories`` (every one where
    none is given) are not said: appended to the list ``into`` where given (the CLI says
    them in its own words), else dropped. Yields ``into``."""
    token = _SCOPES.set(_SCOPES.get() + ((categories or (Warning,), into),))
    try:
        yield into
    finally:
        _SCOPES.reset(token)


def say(message, category=UserWarning, stacklevel: int = 1) -> None:
    """warnings.warn(message, category, stacklevel) unless a :func:`quiet` scope of this
    thread takes the warning (the innermost that does: its list, or nothing)."""
    w = message if isinstance(message, Warning) else category(message)
    for cats, into in reversed(_SCOPES.get()):
        if isinstance(w, cats):
            if into is not None:
                into.append(w)
            return
    warnings.warn(w, stacklevel=stacklevel + 1)


def quieted(category) -> bool:
    """Whether :func:`say` drops warnings of ``category`` in this thread: the innermost
    :func:`quiet` scope that takes them has no list (one that collects them says them,
    there: their text in full, as a recording catch_warnings had it)."""
    for cats, into in reversed(_SCOPES.get()):
        if issubclass(category, cats):
            return into is None
    return False
