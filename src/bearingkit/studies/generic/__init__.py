"""The generic evaluator (``evaluator``): any bearing file or designation × factors that are paths into
its input (``paths``), outputs that are named quantities of the pipeline's Analysis (``quantities``)."""
