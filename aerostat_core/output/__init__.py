"""What leaves the tool for people and other programs: plain-data report tables
(:mod:`~aerostat_core.output.report`, :mod:`~aerostat_core.output.report_parts`), the HTML design
report (:mod:`~aerostat_core.output.html_report`) and geometry exports for CAD and cutting
(:mod:`~aerostat_core.output.export`).

May import: everything below it (physics packages, model, optimize, dynamics, studies).
"""
