import sys

from skcable.cli import main

sys.exit(main())
