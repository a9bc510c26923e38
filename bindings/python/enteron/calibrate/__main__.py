# SPDX-License-Identifier: Apache-2.0
"""python3 -m enteron.calibrate EXPERIMENT.json DATA.csv [options]: see cli.py."""
import sys

from .cli import main

sys.exit(main())
