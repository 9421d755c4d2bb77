# A flat-bottomed die (docs/dies.md): a face over the tube from the axis to x = 7 mm, a concave 3 mm fillet,
# a 45-degree flank to x = 1.3 Ro (Ro = 17.5 mm: the face touches the tube's top at stroke 0).
line 0 17.5 7.0 17.5
arc 7.0 14.5 3.0 90 45
line 9.121320343559642 16.621320343559642 22.75 2.992640687119284
