"""From a validated input document to a bearing model: the builders by ``bearing.type`` (``builders``,
the simpler kinds in ``kinds``), a designation's estimated geometry (``designation``), and the checks
that the rows fit between bore and outside diameter and below the shoulders (``envelope``,
``shoulders``). SI units."""
