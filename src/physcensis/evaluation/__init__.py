"""The paper's evaluation: relation accuracy of scene folders, the baseline methods, and method comparisons."""
