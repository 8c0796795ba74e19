"""Shared start of the end-to-end test scripts: CTest runs each as
/usr/bin/python3 SCRIPT --hexlayer PATH --source DIR; the paths land in `harness.args`."""
import argparse
import sys
import unittest

args = None


def main():
    global args
    parser = argparse.ArgumentParser()
    parser.add_argument("--hexlayer", required=True)
    parser.add_argument("--source", required=True)
    args, rest = parser.parse_known_args()
    unittest.main(module="__main__", argv=[sys.argv[0], *rest], verbosity=2)
