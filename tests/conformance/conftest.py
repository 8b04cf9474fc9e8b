import sys
from pathlib import Path

# test_conformance.py and record.py share _scripts.py beside them
sys.path.insert(0, str(Path(__file__).resolve().parent))
