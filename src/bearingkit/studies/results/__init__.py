"""What a study's results become: designed-experiment analysis (``analysis``), display units
(``display``) and the ``[[plots]]`` a study file asks for (``figures``)."""
