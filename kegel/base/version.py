"""The version of kegel: the installed distribution's, else the compiled core's (a source tree).

It lives here, not in :mod:`kegel`'s ``__init__``, so that the modules that stamp it into their
files (:mod:`kegel.base.io`, :mod:`kegel.runner.run`, the command line) need not import the
package front, which imports them (an import that would run back up the layers).
"""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version as _pkg_version

from .. import _core

__all__ = ["__version__"]

try:
    __version__: str = _pkg_version("kegel")
except PackageNotFoundError:  # pragma: no cover - running from a source tree without install
    __version__ = _core.core_version()
