"""Contact mechanics: Hertz point and line contact, roller profiles (crowning). SI units throughout."""
