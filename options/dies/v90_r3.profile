# The paper's V-die as a profile (docs/dies.md: 90 degrees, apex fillet 3 mm, flanks tangent to the tube of
# Ro = 17.5 mm): the built-in die to the last bit (tests/check_profile.py).
arc 0 20.50609665440988 3.0 90 45
line 2.1213203435596424 22.627416997969522 22.75 1.9987373415291643
