import os
import sys

# seed_tables.py lives beside the tests; the tests read ../shared/ from the project root
sys.path.insert(0, os.path.dirname(__file__))
os.chdir(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
