"""What the paper table scripts share: records, metrics, the document writer, claims.

See docs/pipeline.md. Run everything with Debian's /usr/bin/python3 (python3-matplotlib).
"""
from .records import load_records  # noqa: F401
from .doc import Doc, fmt  # noqa: F401
from . import metrics  # noqa: F401
from . import paper  # noqa: F401
