"""The command line, ``aerostat`` / ``python -m aerostat_core``: the parser and the ``design``
subcommand (:mod:`~aerostat_core.cli.entry`) and the ``envelope``, ``report`` and Monte Carlo
commands (:mod:`~aerostat_core.cli.commands`).

May import: every package of aerostat_core (it is the top).
"""
