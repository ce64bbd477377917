"""The generic report (reports/report.py) in parts: loading, rows, figures, gallery, pages."""
