"""Heat flows out of a bearing and the batched root finder of a heat balance (pure functions)."""
