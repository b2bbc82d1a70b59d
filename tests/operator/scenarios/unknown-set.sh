# A set that does not exist: up, status and down say so at once, naming it.
run "$RGCTL" up no-such-set
expect_refusal "no-such-set"
run "$RGCTL" status no-such-set
expect_refusal "no-such-set"
run "$RGCTL" down no-such-set
expect_refusal "no-such-set"
