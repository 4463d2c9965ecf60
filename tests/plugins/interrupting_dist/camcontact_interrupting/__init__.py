"""While this module is imported, the process receives SIGINT, as when the user presses Ctrl-C."""

import os
import signal
import time

os.kill(os.getpid(), signal.SIGINT)
time.sleep(1.0)  # the signal arrives before the import ends

Film = None
