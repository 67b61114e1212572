# SPDX-License-Identifier: LGPL-2.1-or-later
# Runs one App test module (FEATURELINES_TEST_MODULE, from FEATURELINES_TEST_DIR) under
# freecadcmd and leaves with a real exit code: freecadcmd imports a script given as argument as a
# module and runs it a second time when the import raises, so everything is caught here and the
# process ends with os._exit (0: all tests passed, 1: a failure or no test at all).
import os
import sys
import traceback
import unittest

code = 1
try:
    sys.path.insert(0, os.environ["FEATURELINES_TEST_DIR"])
    suite = unittest.defaultTestLoader.loadTestsFromName(os.environ["FEATURELINES_TEST_MODULE"])
    result = unittest.TextTestRunner(stream=sys.stdout, verbosity=2).run(suite)
    code = 0 if result.wasSuccessful() and result.testsRun > 0 else 1
except BaseException:
    traceback.print_exc()
finally:
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)
