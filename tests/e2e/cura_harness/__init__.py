# MixEngine Cura test harness (test-only plugin for Cura 4.13 / SDK 7.9.0).
# Installed into a throw-away HOME by tests/e2e/cura_driver.py; does nothing unless
# the environment variable CURA_HARNESS_JOB names a job file.
from . import HarnessExtension


def getMetaData():
    return {}


def register(app):
    return {"extension": HarnessExtension.HarnessExtension(app)}
