"""``thermobearing models [FAMILY]``: list registered models with references and ranges."""

from __future__ import annotations

import argparse

from ..citations import reference
from ..errors import UnknownNameError
from ..registry import all_registries

NAME = "models"
HELP = "list the registered models of each family with their references and validity"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("family", nargs="?",
                        help="one family, e.g. heat_source, network_template, film, "
                             "kinematics, stepper (default: all; `thermobearing models` "
                             "prints each family's name in brackets)")


def run(args: argparse.Namespace) -> int:
    registries = all_registries()
    if args.family:
        if args.family not in registries:
            raise UnknownNameError("model family", args.family, registries)
        registries = {args.family: registries[args.family]}
    for family, reg in registries.items():
        print(f"[{family}] {reg.description}")
        for e in reg.entries():
            print(f"  {e.name}: {e.summary}")
            if e.parameters:
                params = ", ".join(
                    f"{k} [{u}]" + (f" in {e.limits[k].text}" if k in e.limits else "")
                    for k, u in e.parameters.items())
                print(f"      parameters: {params}")
            if e.validity:
                print(f"      validity: {e.validity}")
            for key in e.references:
                print(f"      ref: {reference(key).format()}")
        print()
    return 0
