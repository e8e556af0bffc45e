"""What every room shares: errors, atomic files, interrupts, size limits, hints, timers, figures.

Nothing here knows about robots or models; every other subpackage may import from here.
"""
