"""The programmable cellular automaton of thesis chapter 7: rules, engine, patterns, logs."""
