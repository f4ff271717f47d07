from camlab88.cli import main

raise SystemExit(main())
