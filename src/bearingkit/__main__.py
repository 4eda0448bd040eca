from bearingkit.cli import main

main()
