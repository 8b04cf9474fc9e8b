"""Where the interfaces tests keep their data (a module name no other test folder uses)."""
import os

DATA = os.path.join(os.path.dirname(__file__), 'data')
TEST_SHARE = os.path.join(DATA, 'share')
