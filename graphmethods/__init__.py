"""graphmethods: the graphical methods of machine dynamics, exact and to scale.

Importing the package is light: it loads numpy only. The subpackages are, in
import order (each imports only those before it):

``kinematics`` -> ``dynamics`` -> ``problems`` -> ``scene`` -> ``render`` -> ``sheets``

>>> import graphmethods
>>> graphmethods.__version__
'0.1.0'
"""

from graphmethods.errors import GraphmethodsError

__version__ = "0.1.0"
__all__ = ["GraphmethodsError", "__version__"]
