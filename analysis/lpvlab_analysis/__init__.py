"""lpvlab_analysis: turn an lpvlab sweep directory into plots, tables and an HTML report.

Modules, one job each:
  summary       load summary.csv and aggregate repeats per configuration
  pareto        exact Pareto front of (time, error) points
  plots         matplotlib figures (Agg backend, atomic PNG writes)
  tables        Markdown/HTML ablation table with the best metric values in bold
  thesis_tables the thesis's timing tables 8.2-8.7 as data, and trend comparisons
  images        tone-mapping of run/reference EXRs for side-by-side views
  fsutil        atomic file writes
  sections      the sections of kinds of run only some sweeps hold, registered by their modules
                (methods, radiosity, particles)
  report        assemble everything into <out>/index.html
"""
