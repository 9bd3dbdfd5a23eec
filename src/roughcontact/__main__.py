"""Allow ``python -m roughcontact``."""

import sys

from .cli import main

sys.exit(main())
