"""Reports of systems (SI values, display units in the tables and plots): a shaft on several bearings
(``shaft_html``, ``shaft_plots``) and a drivetrain of shafts joined by gear meshes (``drivetrain_html``,
``drivetrain_plots``)."""
