"""The Python helpers shared by scripts/, tools/, studies/ and tests/ (python/README.md): running tubeform and
reading its results (tfruns, analysis), drawing them (figlib, figmaps, fighardening), and the case sets of the
developer tools (validation, tubes, soaklib, extremes). Importing the package imports none of them."""
